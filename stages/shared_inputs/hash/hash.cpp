// Stage `hash`: the random numbers of the trace, made visible (thesis §3.1, §4.3,
// Appendix A), with the hash the `light` stage selects (light.hash) for the trace.
#include "core/frame.h"
#include "shared_inputs/light/light_input.h"
#include "shared_inputs/hash/hash_layout.h"

static_assert(gpu::distinctBelow({HASH_SAMPLES_IMAGE, HASH_BITS_IMAGE}, gpu::kImageUnits));
#include "gl/hash_kind.h"
#include "gl/shader_program.h"

namespace {

class HashStage final : public Stage {
public:
  HashStage() {
    inputs_ = {lightInput()};
    outputs_ = {
        {"samples",
         "First light sample (u, v) in [0,1)^2 of each pixel: the top 24 bits of the first two "
         "hash words, seed = (x, y, 0, 0) (\"screen coordinates are used for the seed\", "
         "Appendix A), key = frame key. Shown as colour: red u, green and blue v. Any "
         "pattern here would show as a pattern in the soft shadows.",
         GL_RG32F, {"u", "v"}, {-1, 0, 1, Colormap::Gray}},
        {"bits",
         "The first hash word of each pixel as a gray level: its top 24 bits / 2^24. Good "
         "hashes look like white noise; changing the frame key changes every pixel.",
         GL_R32F, {"bits"}, {0, 0, 1, Colormap::Gray}},
    };
  }
  std::string name() const override { return "hash"; }
  std::string summary() const override {
    return "Per-pixel random numbers from a hash of the screen coordinates: the first "
           "light sample and the raw bits.";
  }
  std::string thesisSection() const override { return "thesis §3.1, App. A"; }

  void run(Frame& frame) override {
    ShaderProgram& program = programs_[hashSpecialization(frame.light.hashKind)];
    program.use();
    bindLightInput(frame, *this);
    GlTexture& samples = frame.output(*this, "samples", frame.eyeWidth, frame.eyeHeight);
    GlTexture& bits = frame.output(*this, "bits", frame.eyeWidth, frame.eyeHeight);
    glBindImageTexture(HASH_SAMPLES_IMAGE, samples.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
    glBindImageTexture(HASH_BITS_IMAGE, bits.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    dispatchRows(frame.eyeWidth, frame.eyeHeight, kImageResults);
  }

private:
  ShaderVariants programs_{{{GL_COMPUTE_SHADER, "shared_inputs/hash/hash.comp"}}, hashSpecializations()};  // one per hash (hash.glsl)
};

}  // namespace

std::unique_ptr<Stage> makeHashStage() { return std::make_unique<HashStage>(); }

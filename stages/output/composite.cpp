// Stage `composite` (thesis Algorithm 1, last step): the lit scene times the chosen
// shadow stage's visibility.
#include "core/frame.h"
#include "gl/shader_program.h"

namespace {

class CompositeStage final : public Stage {
public:
  CompositeStage() {
    outputs_ = {{"color", "Final image: albedo x (ambient + visibility x Lambert).", GL_RGBA32F,
                 {"R", "G", "B", "A"}, {}}};
    params_ = {
        Param::choice("shadow", "Which stage's visibility shades the image.",
                      {"filter", "trace", "hard_shadow", "none"}, 0),
        Param::real("ambient", "Light that reaches shadowed surfaces (fraction).", 0.2, 0, 1),
    };
  }
  std::string name() const override { return "composite"; }
  std::string summary() const override {
    return "Combines the lit G-buffer with the selected visibility.";
  }
  std::string thesisSection() const override { return "3 (Alg. 1)"; }

  void run(Frame& frame) override {
    const std::string shadow = param("shadow").asEnum();
    const GlTexture& visibility =
        shadow == "none" ? unshadowed(frame) : frame.input(shadow + ".visibility");
    program_.use();
    glBindTextureUnit(0, frame.input("gbuffer.albedo").id());
    glBindTextureUnit(1, frame.input("gbuffer.wsNormal").id());
    glBindTextureUnit(2, frame.input("gbuffer.wsPosition").id());
    glBindTextureUnit(3, visibility.id());
    GlTexture& color = frame.output(*this, "color", frame.eyeWidth, frame.eyeHeight);
    glBindImageTexture(0, color.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatchRows(frame.eyeWidth, frame.eyeHeight);
  }

private:
  const GlTexture& unshadowed(const Frame& frame) {
    if (ones_.width() != frame.eyeWidth || ones_.height() != frame.eyeHeight) {
      ones_ = GlTexture(GL_R32F, frame.eyeWidth, frame.eyeHeight);
      const float one = 1.0f;
      glClearTexImage(ones_.id(), 0, GL_RED, GL_FLOAT, &one);
    }
    return ones_;
  }
  ShaderProgram program_{{{GL_COMPUTE_SHADER, "composite.comp"}}};
  GlTexture ones_;
};

}  // namespace

std::unique_ptr<Stage> makeCompositeStage() { return std::make_unique<CompositeStage>(); }

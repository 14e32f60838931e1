// Stage `pcss`: Percentage-Closer Soft Shadows (Fernando 2005), the baseline of most soft
// shadow demos, on the near layer (shaders/baselines/pcss/pcss.comp has the numbered steps). How it avoids
// the pitfalls users meet in other engines:
//  - light size in world units: the search and filter regions are the light rectangle's cone
//    from the receiver (its world size, through the Eq 3.1 frustum), never a hand-tuned "light
//    size in uv";
//  - one depth space: the map holds linear light depth; blockers are averaged as distances
//    along the light axis and the similar triangles measured from the light plane;
//  - blockers missed at the search border: the search region is cut at the nearest occluder
//    in the whole map (a reduction), so it holds every texel that can block; what the taps
//    still miss (blockers thinner than their spacing) the searchRadius view shows, and the
//    per-pixel shift turns into noise rather than bands.
#include "core/frame.h"
#include "baselines/pcss/gpu_layout_pcss.h"
#include "gl/gpu_layout_ssm.h"
#include "gl/hash_kind.h"
#include "gl/shader_program.h"
#include "gl/tap_patterns.h"
#include "shared/screen_pass_layout.h"
#include "shared_inputs/light/light_input.h"

// Bindings (stages/baselines/pcss/pcss_layout.h), within GL 4.5's minimums.
static_assert(gpu::distinctBelow({FRAME_BLOCK_BINDING, LIGHT_BLOCK_BINDING, PCSS_PARAMS_BINDING},
                                 gpu::kUniformBindings));
static_assert(gpu::distinctBelow({PCSS_TAPS_BINDING, DEPTH_BOUNDS_BINDING}, gpu::kStorageBindings));
static_assert(gpu::distinctBelow({PCSS_NEAR_UNIT, PCSS_WS_POSITION_UNIT, PCSS_WS_NORMAL_UNIT},
                                 gpu::kTextureUnits));
static_assert(gpu::distinctBelow({PCSS_VISIBILITY_IMAGE, PCSS_SEARCH_RADIUS_IMAGE,
                                  PCSS_BLOCKER_DEPTH_IMAGE, PCSS_FILTER_RADIUS_IMAGE},
                                 gpu::kImageUnits));

namespace {

class PcssStage final : public Stage {
public:
  PcssStage() {
    inputs_ = {
        Input::texture("wsPosition", "Receivers (G-buffer).", GL_RGBA32F),
        Input::texture("wsNormal", "Receiver normals (Eq 3.2 bias).", GL_RGBA32F),
        Input::texture("near", "Near layer: the shadow map searched and filtered.",
                       GL_DEPTH_COMPONENT32F),
        lightInput(),
    };
    outputs_ = {
        {"visibility", "Step 4: fraction of filter taps the near layer does not hide.", GL_R32F,
         {"visibility"}, {0, 0, 1, Colormap::Gray}, kRoleShadowMethod},
        {"searchRadius", "Step 1: half-width of the blocker search, in map texels (the light's "
                         "cone cut at the nearest occluder).", GL_R32F, {"texels"},
         {0, 0, 64, Colormap::Perceptual}},
        {"blockerDepth", "Step 2: average linear light depth of the blockers found; 0: none.",
         GL_R32F, {"lsDepth"}, {0, 0, 1, Colormap::Perceptual}},
        {"filterRadius", "Step 3: half-width of the PCF region, in map texels (the light's "
                         "cone cut at the average blocker: the penumbra by similar triangles).",
         GL_R32F, {"texels"}, {0, 0, 32, Colormap::Perceptual}},
    };
    params_ = {
        Param::choice("pattern", "Tap positions: regular n x n grid, or n^2 Poisson-disk points.",
                      {"poisson", "regular"}, 0),
        Param::integer("search_taps", "n: n x n taps of the blocker search.", 5, 1, 16),
        Param::integer("filter_taps", "n: n x n taps of the percentage-closer filter.", 6, 1, 16),
        Param::boolean("shift", "Shift the taps per pixel on the torus of the square region "
                       "(a Cranley-Patterson rotation from the project's hash): noise instead "
                       "of banding.", true),
    };
  }
  std::string name() const override { return "pcss"; }
  std::string summary() const override {
    return "Percentage-closer soft shadows (Fernando 2005): blocker search, average blocker "
           "depth, penumbra width by similar triangles, PCF over it.";
  }
  std::string thesisSection() const override { return "Fernando 2005"; }

  void run(Frame& frame) override {
    const GlTexture& nearLayer = frame.input(*this, "near");
    bindLightInput(frame, *this);
    // The nearest occluder in the map: the plane that cuts the search cone (step 1). Its
    // bounds stay on the GPU: pcss.comp reads them (no wait for the GPU inside the frame).
    const gpu::DepthBounds bounds{0x7f7fffffu, 0u, 0u, 0u};
    boundsBuffer_.upload(&bounds, sizeof bounds);
    boundsProgram_.use();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, DEPTH_BOUNDS_BINDING, boundsBuffer_.id());
    glBindTextureUnit(DEPTH_BOUNDS_MAP_UNIT, nearLayer.id());
    glUniform1f(DEPTH_BOUNDS_EMPTY_LOCATION, 1.0f);
    glDispatchCompute(GLuint((nearLayer.width() + 7) / 8), GLuint((nearLayer.height() + 7) / 8), 1);
    glMemoryBarrier(kBufferResults);

    const TapPattern pattern = param("pattern").asEnum() == "regular" ? TapPattern::Regular : TapPattern::Poisson;
    std::vector<glm::vec2> taps = squareTaps(pattern, param("search_taps").asInt());
    const std::vector<glm::vec2> filter = squareTaps(pattern, param("filter_taps").asInt());
    const int searchCount = int(taps.size());
    taps.insert(taps.end(), filter.begin(), filter.end());
    tapBuffer_.upload(taps.data(), taps.size() * sizeof(glm::vec2));

    gpu::PcssParams params{};
    params.taps = {searchCount, int(filter.size()), param("shift").asBool() ? 1 : 0, 0};
    paramBuffer_.upload(&params, sizeof params);

    ShaderProgram& program = programs_[hashSpecialization(frame.light.hashKind)];
    program.use();
    glBindBufferBase(GL_UNIFORM_BUFFER, PCSS_PARAMS_BINDING, paramBuffer_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, PCSS_TAPS_BINDING, tapBuffer_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, DEPTH_BOUNDS_BINDING, boundsBuffer_.id());
    bindTextureForReading(PCSS_WS_POSITION_UNIT, frame.input(*this, "wsPosition"));
    bindTextureForReading(PCSS_WS_NORMAL_UNIT, frame.input(*this, "wsNormal"));
    glBindTextureUnit(PCSS_NEAR_UNIT, nearLayer.id());
    const std::pair<GLuint, const char*> images[] = {
        {PCSS_VISIBILITY_IMAGE, "visibility"}, {PCSS_SEARCH_RADIUS_IMAGE, "searchRadius"},
        {PCSS_BLOCKER_DEPTH_IMAGE, "blockerDepth"}, {PCSS_FILTER_RADIUS_IMAGE, "filterRadius"}};
    for (const auto& [unit, output] : images)
      glBindImageTexture(unit, frame.output(*this, output, frame.eyeWidth, frame.eyeHeight).id(),
                         0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    dispatchRows(frame.eyeWidth, frame.eyeHeight, kImageResults);
  }

private:
  ShaderVariants programs_{{{GL_COMPUTE_SHADER, "baselines/pcss/pcss.comp"}}, hashSpecializations()};  // one per hash (hash.glsl)
  ShaderProgram boundsProgram_{{{GL_COMPUTE_SHADER, "shared/depth_bounds.comp"}}};
  GlBuffer boundsBuffer_, tapBuffer_, paramBuffer_;
};

}  // namespace

std::unique_ptr<Stage> makePcssStage() { return std::make_unique<PcssStage>(); }

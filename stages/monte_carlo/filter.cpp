// Stage `filter` (thesis §3, Fig 3.2): a separable depth-sensitive Gaussian over the
// trace's unfiltered visibility, horizontal then vertical.
#include <cmath>

#include "core/frame.h"
#include "gl/gpu_layout.h"
#include "gl/shader_program.h"
#include "shared_inputs/light_input.h"
#include "shared/filter_layout.h"
#include "shared/screen_pass_layout.h"

static_assert(gpu::distinctBelow({FILTER_SOURCE_UNIT, FILTER_WS_POSITION_UNIT, FILTER_WS_NORMAL_UNIT,
                                  FILTER_ZRANGE_UNIT},
                                 gpu::kTextureUnits));
static_assert(gpu::distinctBelow({ROW_OFFSET_LOCATION, FILTER_DIRECTION_LOCATION,
                                  FILTER_RADIUS_LOCATION, FILTER_DEPTH_SCALE_LOCATION,
                                  FILTER_NORMAL_POWER_LOCATION, FILTER_PLANE_SIGMA_LOCATION,
                                  FILTER_PIXEL_ANGLE_LOCATION, FILTER_PENUMBRA_SCALE_LOCATION},
                                 gpu::kUniformLocations));

namespace {

class FilterStage final : public Stage {
public:
  FilterStage() {
    inputs_ = {
        Input::texture("visibility", "The visibility to blur (the trace's, unfiltered).", GL_R32F),
        Input::texture("wsPosition", "Receivers: depth differences weight the taps.", GL_RGBA32F),
        Input::texture("wsNormal", "Receiver normals (normal_sensitive, plane_sigma).", GL_RGBA32F),
        Input::texture("zRange", "Occluder depth bounds per pixel (classify): the penumbra "
                                 "width estimate of penumbra_scale.", GL_RGBA32F),
        lightInput(),
    };
    outputs_ = {
        {"horizontal", "After the horizontal pass.", GL_R32F, {"visibility"},
         {0, 0, 1, Colormap::Gray}},
        {"visibility", "Filtered visibility (both passes).", GL_R32F, {"visibility"},
         {0, 0, 1, Colormap::Gray}, kRoleShadowMethod},
    };
    params_ = {
        Param::boolean("enabled", "Blur the shadows (off: the visibility passes through).", true),
        Param::integer("radius", "Filter radius in pixels (sigma = radius / 2).", 4, 0, 32),
        Param::real("depth_scale", "Depth sensitivity per world unit: a sample's weight is "
                                   "divided by 1 + depth_scale x |depth difference| (§3).",
                    20, 0, 1000),
        Param::boolean("normal_sensitive", "Also weight by the normals' agreement, so shadows "
                                           "do not bleed over sharp edges (§3).", true),
        Param::real("plane_sigma",
                    "Geometry: a sample's weight falls as exp(-d^2 / 2 (plane_sigma x pixel)^2), "
                    "d its distance from the centre pixel's tangent plane, pixel the world size "
                    "of one pixel there; 0: off. Keeps the lit top of an occluder from bleeding "
                    "into a contact shadow beside it (issue 12: a plate 0.06 above the ground, "
                    "mean |error| in shadow 0.35 without it).",
                    1.0, 0, 100),
        Param::real("penumbra_scale",
                    "Penumbra width: a pair of pixels is blurred with sigma at most penumbra_scale "
                    "x the smaller of their estimated penumbra widths in pixels (PCSS's estimate "
                    "from classify's nearest occluder); 0: off. Keeps a sharp contact or "
                    "tiny-light shadow sharp.",
                    0.5, 0, 100),
        Param::real("normal_power", "Exponent of max(n_c . n_s, 0) when normal_sensitive.", 8, 1,
                    64),
    };
  }
  std::string name() const override { return "filter"; }
  std::string summary() const override {
    return "Depth-aware separable Gaussian blur of the traced visibility.";
  }
  std::string thesisSection() const override { return "3 (Fig 3.2)"; }

  void run(Frame& frame) override {
    const int w = frame.eyeWidth, h = frame.eyeHeight;
    const int radius = param("enabled").asBool() ? param("radius").asInt() : 0;
    const float normalPower =
        param("normal_sensitive").asBool() ? param("normal_power").asFloat() : 0.0f;
    program_.use();
    glUniform1i(FILTER_RADIUS_LOCATION, radius);
    glUniform1f(FILTER_DEPTH_SCALE_LOCATION, param("depth_scale").asFloat());
    glUniform1f(FILTER_NORMAL_POWER_LOCATION, normalPower);
    glUniform1f(FILTER_PLANE_SIGMA_LOCATION, param("plane_sigma").asFloat());
    glUniform1f(FILTER_PENUMBRA_SCALE_LOCATION, param("penumbra_scale").asFloat());
    glUniform1f(FILTER_PIXEL_ANGLE_LOCATION,
                2.0f * std::tan(glm::radians(frame.scene.camera.fovYDegrees) * 0.5f) / float(h));
    bindLightInput(frame, *this);
    glBindTextureUnit(FILTER_WS_POSITION_UNIT, frame.input(*this, "wsPosition").id());
    glBindTextureUnit(FILTER_WS_NORMAL_UNIT, frame.input(*this, "wsNormal").id());
    glBindTextureUnit(FILTER_ZRANGE_UNIT, frame.input(*this, "zRange").id());
    GlTexture& horizontal = frame.output(*this, "horizontal", w, h);
    pass(frame.input(*this, "visibility"), horizontal, {1, 0}, w, h);
    pass(horizontal, frame.output(*this, "visibility", w, h), {0, 1}, w, h);
  }

private:
  void pass(const GlTexture& source, GlTexture& target, glm::ivec2 direction, int w, int h) {
    glBindTextureUnit(FILTER_SOURCE_UNIT, source.id());
    glBindImageTexture(FILTER_TARGET_IMAGE, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glUniform2i(FILTER_DIRECTION_LOCATION, direction.x, direction.y);
    dispatchRows(w, h);
  }
  ShaderProgram program_{{{GL_COMPUTE_SHADER, "filter.comp"}}};
};

}  // namespace

std::unique_ptr<Stage> makeFilterStage() { return std::make_unique<FilterStage>(); }

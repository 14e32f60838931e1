// Stage `hard_shadow`: the baseline hard shadow (Williams 1978; thesis §2.3).
#include "core/frame.h"
#include "shared_inputs/light/light_input.h"
#include "gl/shader_program.h"
#include "baselines/hard_shadow/hard_shadow_layout.h"
#include "shared/screen_pass_layout.h"

static_assert(gpu::distinctBelow({HARD_SHADOW_NEAR_UNIT, HARD_SHADOW_WS_POSITION_UNIT,
                                  HARD_SHADOW_WS_NORMAL_UNIT}, gpu::kTextureUnits));
static_assert(HARD_SHADOW_VISIBILITY_IMAGE < gpu::kImageUnits);
static_assert(gpu::distinctBelow({ROW_OFFSET_LOCATION, HARD_SHADOW_OFFSET_LOCATION},
                                 gpu::kUniformLocations));

namespace {

class HardShadowStage final : public Stage {
public:
  HardShadowStage() {
    inputs_ = {
        Input::texture("wsPosition", "Receivers (G-buffer).", GL_RGBA32F),
        Input::texture("wsNormal", "Receiver normals (Eq 3.2 bias).", GL_RGBA32F),
        Input::texture("near", "Near layer: the classic shadow map.", GL_DEPTH_COMPONENT32F),
        lightInput(),
    };
    outputs_ = {{"visibility", "1 where the near layer does not hide the point, else 0.",
                 GL_R32F, {"visibility"}, {0, 0, 1, Colormap::Gray}, kRoleShadowMethod}};
    params_ = {
        Param::real("offset", "Depth offset in world units along the light axis, added to the "
                              "light's bias group (light.bias, Eq 3.2): one depth test per "
                              "pixel has no second chance, so it fights shadow acne with a "
                              "little more; too much detaches shadows from their casters.",
                    0.005, 0, 1),
    };
  }
  std::string name() const override { return "hard_shadow"; }
  std::string summary() const override {
    return "Classic shadow-map test (Williams 1978) from the light's projection point: the "
           "baseline.";
  }
  std::string thesisSection() const override { return "thesis §2.3"; }

  void run(Frame& frame) override {
    program_.use();
    bindLightInput(frame, *this);
    bindTextureForReading(HARD_SHADOW_WS_POSITION_UNIT, frame.input(*this, "wsPosition"));
    glBindTextureUnit(HARD_SHADOW_NEAR_UNIT, frame.input(*this, "near").id());
    GlTexture& visibility = frame.output(*this, "visibility", frame.eyeWidth, frame.eyeHeight);
    glBindImageTexture(HARD_SHADOW_VISIBILITY_IMAGE, visibility.id(), 0, GL_FALSE, 0,
                       GL_WRITE_ONLY, GL_R32F);
    bindTextureForReading(HARD_SHADOW_WS_NORMAL_UNIT, frame.input(*this, "wsNormal"));
    glUniform1f(HARD_SHADOW_OFFSET_LOCATION, param("offset").asFloat());
    dispatchRows(frame.eyeWidth, frame.eyeHeight, kImageResults);
  }

private:
  ShaderProgram program_{{{GL_COMPUTE_SHADER, "baselines/hard_shadow/hard_shadow.comp"}}};
};

}  // namespace

std::unique_ptr<Stage> makeHardShadowStage() { return std::make_unique<HardShadowStage>(); }

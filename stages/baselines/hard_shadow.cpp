// Stage `hard_shadow`: the baseline hard shadow (Williams 1978; thesis §2.3).
#include "core/frame.h"
#include "gl/shader_program.h"

namespace {

class HardShadowStage final : public Stage {
public:
  HardShadowStage() {
    outputs_ = {{"visibility", "1 where the near layer does not hide the point, else 0.",
                 GL_R32F, {"visibility"}, {0, 0, 1, Colormap::Gray}}};
    params_ = {
        Param::real("bias", "Constant depth bias in world units along the light axis: fights "
                            "shadow acne; too much detaches shadows from their casters.",
                    0.005, 0, 1),
        Param::boolean("adaptive_bias", "Add the adaptive bias of thesis Eq 3.2 (one texel's "
                                        "world size, divided by n.l).", true),
        Param::real("min_cosine", "Lower clamp of n.l in Eq 3.2, so grazing surfaces get a "
                                  "large but finite bias.", 0.1, 0.001, 1),
    };
  }
  std::string name() const override { return "hard_shadow"; }
  std::string summary() const override {
    return "Classic shadow-map test from the light's projection point: the baseline.";
  }
  std::string thesisSection() const override { return "2.3"; }

  void run(Frame& frame) override {
    program_.use();
    glBindTextureUnit(0, frame.input("gbuffer.wsPosition").id());
    glBindTextureUnit(1, frame.input("light_layers.near").id());
    GlTexture& visibility = frame.output(*this, "visibility", frame.eyeWidth, frame.eyeHeight);
    glBindImageTexture(0, visibility.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glBindTextureUnit(2, frame.input("gbuffer.wsNormal").id());
    glUniform1f(1, param("bias").asFloat());
    glUniform1i(2, param("adaptive_bias").asBool());
    glUniform1f(3, param("min_cosine").asFloat());
    dispatchRows(frame.eyeWidth, frame.eyeHeight);
  }

private:
  ShaderProgram program_{{{GL_COMPUTE_SHADER, "hard_shadow.comp"}}};
};

}  // namespace

std::unique_ptr<Stage> makeHardShadowStage() { return std::make_unique<HardShadowStage>(); }

// Stage `composite` (thesis Algorithm 1, last step): the lit scene times the chosen
// shadow stage's visibility.
#include "core/frame.h"
#include "shared_inputs/light/light_input.h"
#include "gl/screen_triangle.h"
#include "gl/shader_program.h"
#include "output/composite/composite_layout.h"

static_assert(gpu::distinctBelow({COMPOSITE_ALBEDO_UNIT, COMPOSITE_WS_NORMAL_UNIT,
                                  COMPOSITE_WS_POSITION_UNIT, COMPOSITE_VISIBILITY_UNIT},
                                 gpu::kTextureUnits));
static_assert(COMPOSITE_AMBIENT_LOCATION < gpu::kUniformLocations);

namespace {

class CompositeStage final : public Stage {
public:
  CompositeStage() {
    inputs_ = {
        // R32F, as every choice slot (app/core/stage.h): composite.frag reads an r32f image.
        Input::choice("visibility", "The shadow method's visibility that shades the image.",
                      kRoleShadowMethod, "shadow", "filter", /*allowNone=*/true),
        Input::texture("albedo", "Surface colour (G-buffer).", GL_RGBA8),
        Input::texture("wsNormal", "Normals (Lambert).", GL_RGBA32F),
        Input::texture("wsPosition", "Positions (direction to the light).", GL_RGBA32F),
        lightInput(),
    };
    outputs_ = {{"color", "Final image: albedo x (ambient + visibility x Lambert).", GL_RGBA32F,
                 {"R", "G", "B", "A"}, {}}};
    params_ = {
        Param::choice("shadow", "Which shadow method's visibility shades the image (every "
                                "stage whose output is a shadow method's visibility).",
                      {}, 0),  // options: the graph's methods (Pipeline fills them)
        Param::real("ambient", "Light that reaches shadowed surfaces (fraction).", 0.2, 0, 1),
    };
  }
  std::string name() const override { return "composite"; }
  std::string summary() const override {
    return "Combines the lit G-buffer with the selected visibility: color = albedo x "
           "(ambient + visibility x Lambert).";
  }
  std::string thesisSection() const override { return "thesis §3, Alg. 1"; }

  void run(Frame& frame) override {
    const GlTexture& visibility = frame.connected(*this, "visibility")
                                      ? frame.input(*this, "visibility")
                                      : unshadowed(frame);
    program_.use();
    bindLightInput(frame, *this);
    glUniform1f(COMPOSITE_AMBIENT_LOCATION, param("ambient").asFloat());
    bindTextureForReading(COMPOSITE_ALBEDO_UNIT, frame.input(*this, "albedo"));
    bindTextureForReading(COMPOSITE_WS_NORMAL_UNIT, frame.input(*this, "wsNormal"));
    bindTextureForReading(COMPOSITE_WS_POSITION_UNIT, frame.input(*this, "wsPosition"));
    bindTextureForReading(COMPOSITE_VISIBILITY_UNIT, visibility);
    GlTexture& color = frame.output(*this, "color", frame.eyeWidth, frame.eyeHeight);
    screen_.draw(color);
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
  ShaderProgram program_{{{GL_VERTEX_SHADER, "shared/screen_triangle.vert"},
                          {GL_FRAGMENT_SHADER, "output/composite/composite.frag"}}};
  ScreenTriangle screen_;
  GlTexture ones_;
};

}  // namespace

std::unique_ptr<Stage> makeCompositeStage() { return std::make_unique<CompositeStage>(); }

// Stage `flat_shadow`, a test-only shadow method (docs/design.md#add-a-method): this folder
// (the stage, its test) and shaders/tests/stages/test_method/ (its shader and layout header),
// plus the one registry line at the end of this file, are all it takes for a method to
// appear in composite, error, the window, the bench and the all-methods lesson.
#include "core/frame.h"
#include "core/pipeline.h"
#include "gl/gpu_layout.h"
#include "gl/shader_program.h"
#include "shared/screen_pass_layout.h"
#include "flat_shadow_layout.h"

static_assert(FLAT_SHADOW_WS_POSITION_UNIT < gpu::kTextureUnits);
static_assert(FLAT_SHADOW_VISIBILITY_IMAGE < gpu::kImageUnits);
static_assert(gpu::distinctBelow({ROW_OFFSET_LOCATION, FLAT_SHADOW_LEVEL_LOCATION}, gpu::kUniformLocations));

namespace {

class FlatShadowStage final : public Stage {
public:
  FlatShadowStage() {
    inputs_ = {Input::texture("wsPosition", "Receivers (G-buffer): w = 0 where no surface.", GL_RGBA32F)};
    outputs_ = {{"visibility", "level on every receiver, 1 where no surface.", GL_R32F, {"visibility"},
                 {0, 0, 1, Colormap::Gray}, kRoleShadowMethod}};
    params_ = {Param::real("level", "The fraction of the light every receiver sees.", 0.5, 0, 1)};
  }
  std::string name() const override { return "flat_shadow"; }
  std::string summary() const override {
    return "Test-only method: every receiver sees the same fraction of the light.";
  }
  std::string thesisSection() const override { return "tests only"; }

  void run(Frame& frame) override {
    program_.use();
    bindTextureForReading(FLAT_SHADOW_WS_POSITION_UNIT, frame.input(*this, "wsPosition"));
    GlTexture& visibility = frame.output(*this, "visibility", frame.eyeWidth, frame.eyeHeight);
    glBindImageTexture(FLAT_SHADOW_VISIBILITY_IMAGE, visibility.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glUniform1f(FLAT_SHADOW_LEVEL_LOCATION, param("level").asFloat());
    dispatchRows(frame.eyeWidth, frame.eyeHeight, kImageResults);
  }

private:
  ShaderProgram program_{{{GL_COMPUTE_SHADER, "tests/stages/test_method/flat_shadow.comp"}}};
};

}  // namespace

std::unique_ptr<Stage> makeFlatShadowStage() { return std::make_unique<FlatShadowStage>(); }

// The registry line (core/pipeline.h registerTestStage: appended to every registry this
// test binary makes).
extern const bool kFlatShadowRegistered;
const bool kFlatShadowRegistered = registerTestStage(makeFlatShadowStage);

// The window drives stages by their declared capabilities (app/core/stage.h Capability,
// window/ui_graph.h), never by the parameters they happen to declare: two test-only stages
// with the same parameters, one declaring the capabilities and one not, are registered
// (core/pipeline.h registerTestStage) beside the real ones, and a pick reaches only the one
// that declares them.
#include <gtest/gtest.h>

#include "core/pipeline.h"
#include "gl/gpu_scene.h"
#include "scene/scene_builtin.h"
#include "support/gl_test.h"
#include "window/ui_graph.h"
#include "window/ui_state.h"
#include "window/views/ui_ssm_pick.h"
#include "window/views/ui_trace_source.h"

namespace {

constexpr int kMaps = 48;  // the test stages' map size (not ssm's 128)

// Every parameter a pick could set, and a pickedMask; `capable` declares the capabilities.
class PickParamsStage final : public Stage {
public:
  PickParamsStage(std::string name, bool capable) : name_(std::move(name)) {
    outputs_ = {{"picked", "test", GL_R32F, {"v"}, {}, kRoleNone},
                {"pickedMask", "test", GL_R32F, {"v"}, {}, kRoleNone}};
    params_ = {Param::integer("pick_x", "", -1, -1, 9999), Param::integer("pick_y", "", -1, -1, 9999),
               Param::integer("patch_x", "", -1, -1, 9999), Param::integer("patch_y", "", -1, -1, 9999),
               Param::integer("resolution", "", kMaps, 8, 1024)};
    if (capable) capabilities_ = kCapabilityPicksEyePixel | kCapabilityPicksMapTexel | kCapabilityPickedLightMask;
  }
  std::string name() const override { return name_; }
  std::string summary() const override { return "test stage"; }
  std::string thesisSection() const override { return ""; }
  void run(Frame&) override {}

private:
  std::string name_;
};

// Two registry lines, appended after the registry's own: where the window takes one stage
// (raster4d's light mask, the trace's records) it takes the first in execution order.
const bool registered = registerTestStage([] { return std::unique_ptr<Stage>(new PickParamsStage("params_only", false)); }) &&
                        registerTestStage([] { return std::unique_ptr<Stage>(new PickParamsStage("capable", true)); });

}  // namespace

TEST(WindowCapabilities, OnlyStagesDeclaringACapabilityAreFoundByIt) {
  ASSERT_TRUE(registered);
  Pipeline pipeline;
  std::vector<std::string> eyePick;
  for (Stage* stage : stagesThatCan(pipeline, kCapabilityPicksEyePixel)) eyePick.push_back(stage->name());
  EXPECT_EQ(eyePick, (std::vector<std::string>{"ssm", "raster4d", "capable"}));
  std::vector<std::string> mapPick;
  for (Stage* stage : stagesThatCan(pipeline, kCapabilityPicksMapTexel)) mapPick.push_back(stage->name());
  EXPECT_EQ(mapPick, (std::vector<std::string>{"ssm", "capable"}));
  EXPECT_EQ(lightMaskOutput(pipeline), "raster4d.pickedMask");  // the first in order
  ASSERT_NE(recordingStage(pipeline), nullptr);
  EXPECT_EQ(recordingStage(pipeline)->name(), "trace");
}

TEST(WindowCapabilities, APickSetsThePickedPixelOfCapableStagesOnly) {
  ASSERT_TRUE(registered);
  headlessContext();
  UiState state;
  state.session.scene = makeBuiltinScene("plate");
  state.session.gpuScene = std::make_unique<GpuScene>(state.session.scene);
  state.session.frame = std::make_unique<Frame>(state.session.scene, *state.session.gpuScene, state.session.pipeline);
  Frame& frame = *state.session.frame;
  frame.eyeWidth = 64, frame.eyeHeight = 40;
  Pipeline& pipeline = state.session.pipeline;

  // An eye pick (GL texel, row 0 at the bottom): the recorded pixel, and every eye-picking
  // stage's picked pixel in image coordinates (row 0 at the top).
  state.views.pick = glm::ivec2(5, 7);
  state.views.pickSpace = {frame.eyeWidth, frame.eyeHeight};
  recordPickedPixel(state);
  pickStageMapTexels(state);  // not a map-sized pick: changes nothing
  for (const std::string stage : {"capable", "ssm", "raster4d"}) {
    EXPECT_EQ(pipeline.param(stage + ".pick_x").asInt(), 5) << stage;
    EXPECT_EQ(pipeline.param(stage + ".pick_y").asInt(), 40 - 1 - 7) << stage;
  }
  EXPECT_EQ(pipeline.param("trace.record_x").asInt(), 5);
  EXPECT_EQ(pipeline.param("trace.record_y").asInt(), 40 - 1 - 7);
  EXPECT_EQ(pipeline.param("params_only.pick_x").asInt(), -1);
  EXPECT_EQ(pipeline.param("params_only.pick_y").asInt(), -1);
  EXPECT_EQ(pipeline.param("capable.patch_x").asInt(), -1);

  // A pick in a kMaps x kMaps view: the map texel of the capable stage whose maps are that
  // size; not ssm's (128), not the one without the capability.
  state.views.pick = glm::ivec2(11, 13);
  state.views.pickSpace = glm::ivec2(kMaps);
  pickStageMapTexels(state);
  EXPECT_EQ(pipeline.param("capable.patch_x").asInt(), 11);
  EXPECT_EQ(pipeline.param("capable.patch_y").asInt(), 13);
  EXPECT_EQ(pipeline.param("params_only.patch_x").asInt(), -1);
  EXPECT_EQ(pipeline.param("ssm.patch_x").asInt(), -1);
  // ... and in ssm's 128 x 128 maps, ssm's.
  state.views.pickSpace = glm::ivec2(pipeline.param("ssm.resolution").asInt());
  pickStageMapTexels(state);
  EXPECT_EQ(pipeline.param("ssm.patch_x").asInt(), 11);
  EXPECT_EQ(pipeline.param("params_only.patch_x").asInt(), -1);
}

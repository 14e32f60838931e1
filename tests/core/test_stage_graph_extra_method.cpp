// A method the registry does not have, added the way a new one would be (a stage whose
// output has the shadow-method role, one registry line): it appears in the composite's and
// the error's choices and in every bench preset's plan, and is measured like the others.
#include <gtest/gtest.h>

#include <algorithm>

#include "bench/bench_configs.h"
#include "bench/bench_measure.h"
#include "core/pipeline.h"
#include "scene/scene_builtin.h"
#include "support/gl_test.h"

namespace {
class HalfLightStage final : public Stage {
public:
  HalfLightStage() {
    inputs_ = {Input::texture("wsPosition", "receivers", GL_RGBA32F)};
    outputs_ = {{"visibility", "0.5 everywhere", GL_R32F, {"visibility"}, {}, kRoleShadowMethod}};
  }
  std::string name() const override { return "half_light"; }
  std::string summary() const override { return "test-only method"; }
  std::string thesisSection() const override { return ""; }
  void run(Frame& frame) override {
    frame.input(*this, "wsPosition");  // declared and wired
    GlTexture& visibility = frame.output(*this, "visibility", frame.eyeWidth, frame.eyeHeight);
    const float half = 0.5f;
    glClearTexImage(visibility.id(), 0, GL_RED, GL_FLOAT, &half);
  }
};

std::unique_ptr<Pipeline> pipelineWithHalfLight() {
  std::vector<StageEntry> registry = makeRegistry();
  registry.push_back({std::make_unique<HalfLightStage>(), {}});
  return std::make_unique<Pipeline>(std::move(registry));
}
}  // namespace

TEST(StageGraph, AnExtraMethodAppearsInCompositeAndError) {
  auto pipeline = pipelineWithHalfLight();
  const auto methods = pipeline->methods();
  EXPECT_NE(std::find(methods.begin(), methods.end(), "half_light"), methods.end());
  for (const std::string key : {"composite.shadow", "error.method"}) {
    const auto& options = pipeline->param(key).options;
    EXPECT_NE(std::find(options.begin(), options.end(), "half_light"), options.end()) << key;
  }
  // Shading with it: the composite darkens lit receivers by the method's 0.5.
  headlessContext();
  const Scene scene = makeBuiltinScene("plate");
  GpuScene gpuScene(scene);
  Frame frame(scene, gpuScene, *pipeline);
  frame.eyeWidth = 48, frame.eyeHeight = 32;
  ASSERT_EQ(pipeline->set("composite.shadow=none"), "");
  pipeline->run(frame, {"composite.color"});
  const std::vector<float> unshadowed = frame.texture("composite.color").readFloats();
  ASSERT_EQ(pipeline->set("composite.shadow=half_light"), "");
  pipeline->run(frame, {"composite.color"});
  EXPECT_TRUE(pipeline->lastTime("half_light").ran);
  EXPECT_FALSE(pipeline->lastTime("trace").ran);
  const std::vector<float> half = frame.texture("composite.color").readFloats();
  const std::vector<float> albedo = frame.texture("gbuffer.albedo").readFloats();
  const float ambient = pipeline->param("composite.ambient").asFloat();
  int checked = 0;
  for (size_t i = 0; i < half.size(); i += 4) {
    if (albedo[i + 3] == 0 || albedo[i] <= 0) continue;  // background
    // color = albedo (ambient + (1 - ambient) v lambert): with v = 1 and 0.5 the lit part halves.
    const float full = unshadowed[i] / albedo[i] - ambient, halved = half[i] / albedo[i] - ambient;
    EXPECT_NEAR(halved, 0.5f * full, 2e-2f) << "pixel " << i / 4;
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

// ... and in `penumbra bench`'s configurations, with its defaults in every preset, timed over
// exactly the stages its visibility depends on (the G-buffer and itself), and measured
// against the reference like any other method.
TEST(StageGraph, AnExtraMethodAppearsInTheBenchPlanAndIsTimedOverItsStages) {
  auto pipeline = pipelineWithHalfLight();
  const Scene plate = makeBuiltinScene("plate");
  const Scene toys = makeBuiltinScene("toys");  // the animated preset needs an animation
  for (const std::string& preset : benchPresetNames()) {
    const Scene& scene = preset == "animated" ? toys : plate;
    const std::vector<BenchSetup> plan = makeBenchPlan(scene, {preset, {}, 0, 0}, *pipeline);
    size_t found = 0;
    for (const BenchSetup& setup : plan)
      for (const BenchConfig& config : setup.configs) {
        if (config.method != "half_light") continue;
        ++found;
        EXPECT_EQ(config.family, "half_light");
        const ParamSnapshot defaults(*pipeline);
        EXPECT_EQ(applySets(*pipeline, config.sets), "") << config.label;
        EXPECT_EQ(pipeline->param("error.method").asEnum(), "half_light");
        EXPECT_EQ(pipeline->param("composite.shadow").asEnum(), "half_light");
        defaults.restore();
      }
    EXPECT_GT(found, 0u) << preset;
    // The real registry's plan does not have it.
    for (const BenchSetup& setup : makeBenchPlan(scene, {preset, {}, 0, 0}, Pipeline()))
      for (const BenchConfig& config : setup.configs) EXPECT_NE(config.method, "half_light");
  }
  EXPECT_EQ(timedStages(*pipeline, "half_light"), (std::vector<std::string>{"gbuffer", "half_light"}));

  // Measured like the others: error against the reference, then timed frames.
  headlessContext();
  GpuScene gpuScene(plate);
  Frame frame(plate, gpuScene, *pipeline);
  frame.eyeWidth = 48, frame.eyeHeight = 32;
  const auto plan = makeBenchPlan(plate, {"minimal", {}, 48, 32}, *pipeline);
  const BenchConfig& config = *std::find_if(plan[0].configs.begin(), plan[0].configs.end(),
                                            [](const BenchConfig& c) { return c.method == "half_light"; });
  ASSERT_EQ(applySets(*pipeline, config.sets), "");
  ASSERT_EQ(pipeline->set("reference.cache=false"), "");
  BenchResult result;
  ASSERT_TRUE(measureError(*pipeline, frame, 0, config, 2, result));
  EXPECT_EQ(result.stages, (std::vector<std::string>{"gbuffer", "half_light"}));
  EXPECT_GT(result.error.pixels, 0u);
  EXPECT_GT(result.error.meanAbsInShadow, 0.0);  // 0.5 is not the truth anywhere in shadow
  FrameTimes times;
  for (int i = 0; i < 3; ++i) timeFrame(*pipeline, frame, result, std::uint32_t(i + 1), &times);
  summarize(times, result);
  EXPECT_FALSE(pipeline->lastTime("trace").ran);  // only its own stages ran
  EXPECT_EQ(result.frames, 3);
  ASSERT_EQ(result.stageMs.size(), 2u);
  EXPECT_GE(result.msMedian, result.stageMs.at("half_light"));
  EXPECT_GT(result.msMedian, 0.0);
}

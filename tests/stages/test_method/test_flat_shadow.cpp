// A new shadow method is one folder and one registry line (docs/design.md#add-a-method):
// `flat_shadow` (flat_shadow.cpp beside this file, its shader in
// shaders/tests/stages/test_method/) is registered by its own file, and with no other edit it
// is a method of every pipeline this binary builds: composite's and error's choices, the
// window's lists, the bench's plan and the all-methods lesson.
#include <gtest/gtest.h>

#include <algorithm>

#include "base/json_input.h"
#include "bench/bench_configs.h"
#include "bench/bench_report.h"
#include "core/pipeline.h"
#include "gl/gpu_scene.h"
#include "scene/scene_builtin.h"
#include "support/gl_test.h"
#include "window/script/ui_script.h"
#include "window/ui_state.h"

extern const bool kFlatShadowRegistered;  // flat_shadow.cpp's registry line

namespace {

bool contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

}  // namespace

TEST(TestMethod, ItIsAMethodInCompositeAndErrorChoices) {
  ASSERT_TRUE(kFlatShadowRegistered);
  Pipeline pipeline;
  EXPECT_TRUE(contains(pipeline.methods(), "flat_shadow"));
  EXPECT_EQ(pipeline.methodOutput("flat_shadow"), "flat_shadow.visibility");
  EXPECT_TRUE(contains(pipeline.param("composite.shadow").options, "flat_shadow"));
  EXPECT_TRUE(contains(pipeline.param("error.method").options, "flat_shadow"));
  // error.against lists ground truths; flat_shadow declares no such role, so it is not one.
  EXPECT_FALSE(contains(pipeline.param("error.against").options, "flat_shadow"));
  EXPECT_TRUE(contains(pipeline.param("error.against").options, "reference"));
  // --set reaches its parameter, range-checked where it is declared.
  EXPECT_EQ(pipeline.set("flat_shadow.level=0.25"), "");
  EXPECT_NE(pipeline.set("flat_shadow.level=2"), "");
}

// Its shader runs: the visibility is `level` exactly where the G-buffer has a surface, 1
// elsewhere (the oracle: the G-buffer's own coverage), and composite shades with it.
TEST(TestMethod, ItRunsAndCompositeShadesWithIt) {
  headlessContext();
  Pipeline pipeline;
  const Scene scene = makeBuiltinScene("plate");
  GpuScene gpuScene(scene);
  Frame frame(scene, gpuScene, pipeline);
  frame.eyeWidth = 48, frame.eyeHeight = 32;
  ASSERT_EQ(pipeline.set("flat_shadow.level=0.25"), "");
  ASSERT_EQ(pipeline.set("composite.shadow=flat_shadow"), "");
  pipeline.run(frame, {"composite.color"});
  EXPECT_TRUE(pipeline.lastTime("flat_shadow").ran);
  EXPECT_FALSE(pipeline.lastTime("trace").ran);
  const std::vector<float> visibility = frame.texture("flat_shadow.visibility").readFloats();
  const std::vector<float> position = frame.texture("gbuffer.wsPosition").readFloats();
  ASSERT_EQ(visibility.size() * 4, position.size());
  size_t covered = 0;
  for (size_t i = 0; i < visibility.size(); ++i) {
    const bool surface = position[4 * i + 3] > 0;
    covered += surface;
    ASSERT_EQ(visibility[i], surface ? 0.25f : 1.0f) << "pixel " << i;
  }
  EXPECT_GT(covered, visibility.size() / 4);
}

// The window's lists: the outputs a view offers and the choices the pipeline panel draws
// come from the session's pipeline, which is the registry's.
TEST(TestMethod, TheWindowListsIt) {
  UiState state;
  EXPECT_TRUE(contains(state.session.pipeline.methods(), "flat_shadow"));
  EXPECT_TRUE(contains(state.session.outputKeys(), "flat_shadow.visibility"));
  EXPECT_TRUE(contains(state.session.pipeline.param("composite.shadow").options, "flat_shadow"));
  EXPECT_TRUE(contains(state.session.pipeline.param("error.method").options, "flat_shadow"));
  EXPECT_NE(state.session.outputOf("flat_shadow.visibility"), nullptr);
}

// The bench (and the window's speed-against-error tab, which plans with a fresh Pipeline):
// one configuration with its defaults in every preset, timed over the G-buffer and itself.
TEST(TestMethod, TheBenchPlansAndTimesIt) {
  Pipeline pipeline;
  const Scene plate = makeBuiltinScene("plate");
  const Scene toys = makeBuiltinScene("toys");  // the animated preset needs an animation
  for (const std::string& preset : benchPresetNames()) {
    const Scene& scene = preset == "animated" ? toys : plate;
    size_t found = 0;
    for (const BenchSetup& setup : makeBenchPlan(scene, {preset, {}, 0, 0}, pipeline))
      for (const BenchConfig& config : setup.configs)
        if (config.method == "flat_shadow") {
          ++found;
          EXPECT_TRUE(contains(config.sets, "composite.shadow=flat_shadow")) << config.label;
          EXPECT_TRUE(contains(config.sets, "error.method=flat_shadow")) << config.label;
        }
    EXPECT_GT(found, 0u) << preset;
  }
  EXPECT_EQ(timedStages(pipeline, "flat_shadow"), (std::vector<std::string>{"gbuffer", "flat_shadow"}));
}

// The all-methods lesson plays its for_each_method once per method of the registry: the
// committed lessons/all_methods.json, expanded over this binary's pipeline, shows, measures
// and exports flat_shadow after raster4d (the seventh method, panel g).
TEST(TestMethod, TheAllMethodsLessonShowsIt) {
  std::vector<ScriptAction> actions;
  ASSERT_EQ(parseScriptFile(std::string(PENUMBRA_SOURCE_DIR) + "/lessons/all_methods.json", actions), "");
  const auto loop = std::find_if(actions.begin(), actions.end(),
                                 [](const ScriptAction& a) { return a.name == "for_each_method"; });
  ASSERT_NE(loop, actions.end()) << "the lesson lists its methods by hand";
  UiState state;
  const auto expanded = expandForEachMethod(state.session.pipeline, loop->argument);
  const std::vector<std::string> methods = state.session.pipeline.methods();
  ASSERT_EQ(expanded.size(), loop->argument.size() * methods.size());
  ASSERT_EQ(methods.back(), "flat_shadow");
  bool selected = false, measured = false, exported = false, collected = false;
  for (const auto& [name, argument] : expanded) {
    selected |= name == "select_output" && argument == "flat_shadow.visibility";
    measured |= name == "set" && argument.value("error.method", "") == "flat_shadow";
    if (name == "export_view" && argument.value("file", "") == "g_flat_shadow.png") {
      exported = true;
      // Charged for its own stage: the G-buffer is shared by every method.
      EXPECT_NE(argument.value("caption", "").find("{ms:flat_shadow}"), std::string::npos) << argument.dump();
      EXPECT_NE(argument.value("caption", "").find("tests only"), std::string::npos) << argument.dump();
    }
    if (name == "collect")
      for (const auto& [key, text] : argument.items())
        collected |= text.get<std::string>().rfind("flat_shadow {ms:flat_shadow} ms", 0) == 0;
    EXPECT_EQ(argument.dump().find("{method"), std::string::npos) << name << ": " << argument.dump();
  }
  EXPECT_TRUE(selected);
  EXPECT_TRUE(measured);
  EXPECT_TRUE(exported);
  EXPECT_TRUE(collected);
}

// The window runs only what it shows (docs/design.md#stage-graph): with gbuffer.albedo in the view
// only the G-buffer runs and the timings say "not run" for the rest; the composite runs its whole
// dependency closure; toggling a parameter starts a new timing series, so the new cost shows after
// one run. Also the run key: nothing re-runs while nothing changes.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "scene/scene_builtin.h"
#include "support/command.h"
#include "support/window_test.h"
#include "window/ui_state.h"

namespace fs = std::filesystem;

namespace {

// The block that `print_timing` printed under `label`, up to the next block.
std::string timingBlock(const std::string& output, const std::string& label) {
  const size_t start = output.find("timing " + label + ":");
  if (start == std::string::npos) return "";
  const size_t end = output.find("\ntiming ", start + 1);
  return output.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

// The stage's line in a block: "  trace            not run" or "  trace  12.3 ms (last ...".
std::string stageLine(const std::string& block, const std::string& stage) {
  const size_t at = block.find("\n  " + stage + " ");
  if (at == std::string::npos) return "";
  return block.substr(at + 1, block.find('\n', at + 1) - at - 1);
}

}  // namespace

TEST(WindowDemand, OnlyTheShownOutputsRunAndANewParameterStartsANewSeries) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("window_demand");
  const auto script = writeScript(dir, R"([{"eye_size": [96, 64]},
    {"select_output": "gbuffer.albedo"}, {"wait": 2}, {"print_timing": "albedo"},
    {"select_output": "composite.color"}, {"wait": 2}, {"print_timing": "composite"},
    {"set": {"filter.enabled": false}}, {"print_timing": "filter off"}])");
  const auto result = runPenumbra("--script " + script.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const std::string albedo = timingBlock(result.output, "albedo");
  ASSERT_FALSE(albedo.empty()) << result.output;
  EXPECT_NE(stageLine(albedo, "gbuffer").find(" ms (last "), std::string::npos) << albedo;
  for (const char* stage :
       {"light", "light_layers", "nbuffer", "minmax", "classify", "trace", "filter", "composite"})
    EXPECT_NE(stageLine(albedo, stage).find("not run"), std::string::npos) << stage << "\n"
                                                                           << albedo;
  const std::string composite = timingBlock(result.output, "composite");
  for (const char* stage :
       {"gbuffer", "light", "light_layers", "classify", "trace", "filter", "composite"})
    EXPECT_NE(stageLine(composite, stage).find(" ms (last "), std::string::npos) << stage << "\n"
                                                                                 << composite;
  // One hierarchy, the one trace.hierarchy=auto chose (docs/decisions/027-auto-hierarchy-rule.md),
  // not both.
  const bool nbuffer = stageLine(composite, "nbuffer").find(" ms (last ") != std::string::npos;
  const bool minmax = stageLine(composite, "minmax").find(" ms (last ") != std::string::npos;
  EXPECT_NE(nbuffer, minmax) << composite;
  EXPECT_NE(stageLine(composite, "reference").find("not run"), std::string::npos) << composite;
  // The filter's series restarted with the parameter: its median covers the one new run.
  const std::string off = timingBlock(result.output, "filter off");
  EXPECT_NE(stageLine(off, "filter").find(", 1 runs)"), std::string::npos) << off;
  fs::remove_all(dir);
}

TEST(WindowDemand, TheRunKeyFollowsParametersCameraViewsAndNothingElse) {
  UiState state;
  state.session.scene = makeBuiltinScene("cube");
  state.views.panels[0].output = "gbuffer.albedo";
  EXPECT_EQ(state.requestedOutputs(), std::vector<std::string>{"gbuffer.albedo"});
  const RunKey before = state.currentKey();
  EXPECT_EQ(state.currentKey(), before);  // nothing changed: no run
  state.status = "a message";             // neither do messages or view settings
  state.views.panels[0].settings.black = 0.25f;
  EXPECT_EQ(state.currentKey(), before);
  ASSERT_EQ(state.session.setParameter("filter.enabled", "false"), "");
  EXPECT_NE(state.currentKey().revision, before.revision);
  RunKey moved = state.currentKey();
  state.session.scene.camera.position.x += 0.5f;
  EXPECT_NE(state.currentKey().scene, moved.scene);
  state.views.layout = ViewLayout::SideBySide;
  state.views.panels[1].output = "light_layers.far";
  state.views.panels[1].minus = "light_layers.near";
  EXPECT_EQ(state.requestedOutputs(),
            (std::vector<std::string>{"gbuffer.albedo", "light_layers.far", "light_layers.near"}));
}

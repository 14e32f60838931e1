// The window's log (app/window/ui_log.h): every warning and error of the session, whole, with
// time and source: scene warnings once when they appear, failed runs, failed actions and
// exports; repeats counted, not repeated; in window mode the same lines on stderr, and a
// script reads them back ("print_log"). The status line's text is cut with "..." to fit.
#include <gtest/gtest.h>

#include <imgui.h>

#include "scene/scene_builtin.h"
#include "support/gl_test.h"
#include "support/scene_writer.h"
#include "support/window_test.h"
#include "window/panels/ui_export.h"
#include "window/ui_log_panel.h"
#include "window/ui_state.h"

namespace {

int entriesFrom(const UiLog& log, const std::string& source) {
  int n = 0;
  for (const LogEntry& entry : log.entries()) n += entry.source == source;
  return n;
}

}  // namespace

TEST(WindowLog, WarningsAndErrorsOfTheSessionAreLoggedWholeOnce) {
  headlessContext();
  UiState state;
  std::vector<std::string> warnings;
  state.adoptScene(loadScene("cube", warnings), "cube");
  EXPECT_EQ(state.log.entries().size(), 0u) << state.log.text();
  state.session.eye.fitView = false;
  state.session.eye.width = 64;
  state.session.eye.height = 48;

  // A light turned to the sky: one warning, logged when it appears, not again while it stays.
  state.session.scene.light.forward = {0, 1, 0};
  state.session.scene.light.up = {0, 0, -1};
  state.runIfNeeded({64, 48});
  state.session.scene.light.center.x += 0.25f;  // moved, still facing away
  state.runIfNeeded({64, 48});
  ASSERT_EQ(state.log.warnings(), 1) << state.log.text();
  EXPECT_EQ(state.log.entries().back().source, "scene");
  EXPECT_EQ(state.log.entries().back().message, state.sceneWarnings.at(0));  // whole
  EXPECT_EQ(state.log.entries().back().clock.size(), 8u) << "HH:MM:SS";

  // A failed run: an error from the pipeline, with the whole message.
  state.session.scene.light = state.session.initialLight;
  state.session.eye.width = 1 << 20;
  EXPECT_FALSE(state.runIfNeeded({64, 48}));
  ASSERT_EQ(state.log.errors(), 1) << state.log.text();
  EXPECT_EQ(state.log.entries().back().source, "pipeline");
  EXPECT_NE(state.log.entries().back().message.find("pipeline failed"), std::string::npos);
  EXPECT_TRUE(state.statusIsProblem());

  // Failed actions: a refused export, an unknown output; the same failure again is a repeat.
  state.reportExport(exportViewFiles(state, state.views.panels[0], "", ExportKind::Png));
  EXPECT_EQ(entriesFrom(state.log, "export"), 1) << state.log.text();
  EXPECT_NE(state.selectOutput("nothing.here"), "");
  EXPECT_NE(state.selectOutput("nothing.here"), "");
  EXPECT_EQ(entriesFrom(state.log, "view"), 1) << state.log.text();
  EXPECT_EQ(state.log.entries().back().repeats, 2);
  EXPECT_EQ(state.log.errors(), 3);
  EXPECT_NE(state.log.text().find("(x2)"), std::string::npos) << state.log.text();

  // A good run again: the status is no longer a problem; the log keeps what happened.
  state.session.eye.width = 64;
  EXPECT_TRUE(state.runIfNeeded({64, 48}));
  state.status = "shaders reloaded";
  EXPECT_FALSE(state.statusIsProblem());
  EXPECT_EQ(state.log.errors(), 3);
}

// In window mode the log's lines reach the terminal too (scene warnings were not printed at
// all): a loader warning and a light warning, then the script reads the log back.
TEST(WindowLog, WindowModePrintsTheLogOnStderrAndScriptsReadIt) {
  REQUIRE_DISPLAY();
  const TempDirectory dir("penumbra_window_log");
  nlohmann::json scene = groundAndPlateScene();
  scene["light"]["forward"] = {0, 1, 0};    // faces the sky: nothing in the light's layers
  scene["light"]["up"] = {0, 0.5, -1};     // not perpendicular: the loader corrects it, saying so
  const std::string sceneFile = dir.write("sky.json", scene.dump());
  const auto script = writeScript(dir.path(), R"([{"print_log": "end"}])");
  const CommandResult run = runPenumbra("--width 400 --height 300 --scene " + sceneFile + " --script " + script.string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("penumbra: warning scene: " + sceneFile + ": /light/up: not perpendicular"),
            std::string::npos) << run.output;
  EXPECT_NE(run.output.find("penumbra: warning scene: the light faces away"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("log end: 2 warnings, 0 errors"), std::string::npos) << run.output;
}

// The status line's left text is cut with "..." at the room it has, never past it.
TEST(WindowLog, ElidedTextFitsItsRoom) {
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  io.DisplaySize = {640, 480};
  io.DeltaTime = 1.0f / 60;
  ImGui::NewFrame();
  const std::string warning = "warning: the light sits inside occluder 'Stanford_Bunny': hard_shadow, classify and trace clip it";
  const float full = ImGui::CalcTextSize(warning.c_str()).x;
  EXPECT_EQ(elided(warning, full + 1), warning);
  for (float room : {full - 1, 0.5f * full, 60.0f, 30.0f}) {
    const std::string cut = elided(warning, room);
    EXPECT_LE(ImGui::CalcTextSize(cut.c_str()).x, room) << cut;
    ASSERT_GE(cut.size(), 3u);
    EXPECT_EQ(cut.substr(cut.size() - 3), "...") << cut;
    EXPECT_EQ(warning.rfind(cut.substr(0, cut.size() - 3), 0), 0u) << "a prefix: " << cut;
  }
  EXPECT_EQ(elided(warning, 5), "");
  ImGui::EndFrame();
  ImGui::DestroyContext();
}

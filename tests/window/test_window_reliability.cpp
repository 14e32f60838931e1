// Reliability in the window (docs/reliability.md): after a failed pipeline run the frame holds new,
// blank and stale outputs side by side, so every export is refused, saying why, until a run
// succeeds; the status line's light warnings follow the light.
#include <gtest/gtest.h>

#include <filesystem>

#include "scene/scene_builtin.h"
#include "support/gl_test.h"
#include "support/scene_writer.h"
#include "window/panels/ui_export.h"
#include "window/ui_state.h"

namespace fs = std::filesystem;

TEST(WindowReliability, ExportsAreRefusedAfterAFailedRunAndSayWhy) {
  headlessContext();
  const TempDirectory dir("penumbra_window_refuse");
  UiState state;
  std::vector<std::string> warnings;
  state.adoptScene(loadScene("cube", warnings), "cube");
  state.session.eye.fitView = false;
  state.session.eye.width = 64;
  state.session.eye.height = 48;
  ASSERT_EQ(state.selectOutput("composite.color"), "");
  ASSERT_TRUE(state.runIfNeeded({64, 48}));
  EXPECT_EQ(exportAllStages(state, (dir.path() / "good").string()).rfind("wrote ", 0), 0u);

  state.session.eye.width = 1 << 20;  // past the driver's texture size: the run fails part way
  EXPECT_FALSE(state.runIfNeeded({64, 48}));
  EXPECT_NE(state.status.find("pipeline failed"), std::string::npos) << state.status;
  const std::string view = exportViewFiles(state, state.views.panels[0],
                                           (dir.path() / "view.png").string(), ExportKind::Png);
  EXPECT_EQ(view.rfind("export refused", 0), 0u) << view;
  EXPECT_NE(view.find("texture"), std::string::npos) << "does not say why: " << view;
  EXPECT_FALSE(fs::exists(dir.path() / "view.png"));
  const std::string all = exportAllStages(state, (dir.path() / "bad").string());
  EXPECT_EQ(all.rfind("export refused", 0), 0u) << all;
  EXPECT_FALSE(fs::exists(dir.path() / "bad"));

  state.session.eye.width = 64;  // a good run again: exports work again
  ASSERT_TRUE(state.runIfNeeded({64, 48}));
  EXPECT_EQ(exportViewFiles(state, state.views.panels[0], (dir.path() / "view.png").string(),
                            ExportKind::Png).rfind("wrote ", 0), 0u);
  EXPECT_EQ(exportAllStages(state, (dir.path() / "good").string()).rfind("wrote ", 0), 0u);
}

// The status line's warnings follow the light (case 6 in the window).
TEST(WindowReliability, SceneWarningsFollowTheLight) {
  headlessContext();
  UiState state;
  std::vector<std::string> warnings;
  state.adoptScene(loadScene("cube", warnings), "cube");
  EXPECT_TRUE(state.sceneWarnings.empty());
  state.session.eye.fitView = false;
  state.session.scene.light.forward = {0, 1, 0};  // turned to face the sky
  state.session.scene.light.up = {0, 0, -1};
  state.runIfNeeded({64, 48});
  ASSERT_EQ(state.sceneWarnings.size(), 1u);
  EXPECT_NE(state.sceneWarnings[0].find("faces away"), std::string::npos) << state.sceneWarnings[0];
  state.session.scene.light = state.session.initialLight;
  state.runIfNeeded({64, 48});
  EXPECT_TRUE(state.sceneWarnings.empty());
}

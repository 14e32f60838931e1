// The window's time (Session::setTime, app/window/ui_timeline.h): posing the scene, the run
// key, the user's camera kept, scripts' time and play, settings' time, the timeline's clock.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "scene/animation.h"
#include "scene/scene_builtin.h"
#include "support/gl_test.h"
#include "window/script/ui_script.h"
#include "window/script/ui_script_actions.h"
#include "window/script/ui_settings.h"
#include "window/ui_state.h"
#include "window/ui_timeline.h"

using nlohmann::json;

namespace {

void useLightSweep(UiState& state) {
  headlessContext();
  std::vector<std::string> warnings;
  state.adoptScene(loadScene("light_sweep", warnings), "light_sweep");
}

}  // namespace

TEST(WindowTime, SetTimePosesTheSceneKeepsTheCameraAndChangesTheRunKey) {
  UiState state;
  useLightSweep(state);
  ASSERT_TRUE(state.session.animated());
  EXPECT_FLOAT_EQ(state.session.scene.light.width, 0.4f);
  const RunKey atZero = state.currentKey();
  state.session.scene.camera.position = {0.25f, 3.5f, 6};  // the user orbits
  ASSERT_EQ(state.session.setTime(1.5), "");
  EXPECT_FLOAT_EQ(state.session.scene.light.width, 1.4f);  // halfway from 0.4 to 2.4
  EXPECT_EQ(state.session.scene.camera.position, glm::vec3(0.25f, 3.5f, 6));
  EXPECT_EQ(state.session.scene.time, 1.5);
  const RunKey atHalf = state.currentKey();
  EXPECT_EQ(atHalf.time, 1.5);
  EXPECT_FALSE(atHalf == atZero);
  // A new scene starts at time 0.
  useLightSweep(state);
  EXPECT_EQ(state.session.time, 0);
  EXPECT_FLOAT_EQ(state.session.scene.light.width, 0.4f);
}

TEST(WindowTime, ScriptTimeAndPlayActions) {
  UiState state;
  useLightSweep(state);
  std::vector<ScriptAction> actions;
  ASSERT_EQ(parseScriptJson(json::parse(R"([{"time": 3}, {"play": true}])"), actions), "");
  ScriptRunner runner(actions);
  ScriptRunner::Step step = ScriptRunner::Step::Running;
  for (int frame = 0; frame < 10 && step == ScriptRunner::Step::Running; ++frame) step = runner.step(state);
  EXPECT_EQ(step, ScriptRunner::Step::Done) << runner.error();
  EXPECT_EQ(state.session.time, 3);
  EXPECT_FLOAT_EQ(state.session.scene.light.width, 2.4f);
  EXPECT_TRUE(state.session.playing);
  std::vector<ScriptAction> bad;
  EXPECT_NE(parseScriptJson(json::parse(R"([{"time": "soon"}])"), bad), "");
  EXPECT_NE(parseScriptJson(json::parse(R"([{"play": 1}])"), bad), "");
}

TEST(WindowTime, SettingsCarryTheTime) {
  UiState original;
  useLightSweep(original);
  ASSERT_EQ(original.session.setTime(0.75), "");
  const json saved = settingsJson(original);
  EXPECT_EQ(saved["time"].get<double>(), 0.75);
  UiState loaded;
  useLightSweep(loaded);
  ASSERT_EQ(applySettingsJson(loaded, json::parse(saved.dump())), "");
  EXPECT_EQ(loaded.session.time, 0.75);
  EXPECT_EQ(loaded.session.scene.light.width, original.session.scene.light.width);
  EXPECT_NE(applySettingsJson(loaded, json::parse(R"({"time": "later"})")), "");
}

TEST(WindowTime, PlayingAdvancesBySpeedTimesTheClock) {
  UiState state;
  useLightSweep(state);
  TimelineClock clock;
  EXPECT_EQ(advanceTimeline(state.session, clock, 10.0), "");
  EXPECT_EQ(state.session.time, 0) << "paused: the time stays";
  state.session.playing = true;
  state.session.speed = 2;
  EXPECT_EQ(advanceTimeline(state.session, clock, 10.125), "");
  EXPECT_DOUBLE_EQ(state.session.time, 0.25);
  // A stall of seconds moves at most a quarter second (times the speed).
  EXPECT_EQ(advanceTimeline(state.session, clock, 15.0), "");
  EXPECT_DOUBLE_EQ(state.session.time, 0.75);
}

// "Frame scene" on an animated scene frames it at rest and keeps its animation and time.
TEST(WindowTime, FrameSceneKeepsTheAnimationAndTheTime) {
  UiState state;
  useLightSweep(state);
  ASSERT_EQ(state.session.setTime(1.5), "");
  ASSERT_EQ(frameLoadedScene(state), "");
  EXPECT_TRUE(state.session.animated());
  EXPECT_EQ(state.session.time, 1.5);
  EXPECT_FLOAT_EQ(state.session.scene.light.width, 1.4f);  // the track's, at 1.5 s
}

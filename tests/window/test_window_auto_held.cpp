// `auto` while the timeline plays (light.auto_while_playing, docs/decisions/141): a run the
// window makes while playing keeps the last choice and casts no analysis ray, the frustum fit
// still following the pose; Pause runs again and decides at the pose as the static scene does
// from scratch; a new eye size decides anew; scripts, exports and every_frame never hold.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scene/animation.h"
#include "scene/light_frame.h"
#include "scene/scene_builtin.h"
#include "shared_inputs/light/auto_frustum.h"
#include "shared_inputs/light/auto_settings.h"
#include "support/gl_test.h"
#include "window/ui_state.h"
#include "window/ui_timeline.h"

namespace {

const std::vector<std::string> kLight = {"light.light"};

// The oracle: chooseAutoSettings on the static scene posed at t, as the light stage's
// inputs make it (auto field of view), with no stage and no history.
AutoSettings fromScratch(const Scene& animated, double t, int width, int height) {
  Scene posed = poseAt(animated, t);
  posed.animation = Animation{};
  posed.time = 0;
  const FrustumFit fit = fitLightFrustum(posed, 150);
  const LightFrame light = computeLightFrame(posed.light, posed.bounds(), float(fit.fovDegrees));
  return chooseAutoSettings(posed, light, width, height);
}

double counter(const Session& session, const std::string& name) {
  return session.frame->counters.at(name);
}

void run(Session& session) {
  std::string problem;
  ASSERT_TRUE(session.runIfNeeded({0, 0}, kLight, problem)) << problem;
}

// The light_sweep scene: the light grows from 0.4 to 2.4 wide over a box, so the smallest
// penumbra, and with it the map size `auto` needs, changes with the pose.
void useLightSweep(UiState& state, int width, int height) {
  headlessContext();
  std::vector<std::string> warnings;
  state.adoptScene(loadScene("light_sweep", warnings), "light_sweep");
  state.session.eye.fitView = false;
  state.session.eye.width = width, state.session.eye.height = height;
}

}  // namespace

TEST(WindowAutoHeld, PlayingHoldsTheChoiceAndPauseDecidesAtThePose) {
  UiState state;
  useLightSweep(state, 160, 120);
  Session& session = state.session;
  const Scene animated = session.rest;
  const double start = 0.25, later = 3.0;
  // The oracle first: the two poses need different things (else holding would show nothing).
  const AutoSettings atStart = fromScratch(animated, start, 160, 120);
  const AutoSettings atLater = fromScratch(animated, later, 160, 120);
  ASSERT_NE(atStart.neededResolution, atLater.neededResolution);

  // Paused at `start`: decided there.
  ASSERT_EQ(session.setTime(start), "");
  run(session);
  EXPECT_EQ(counter(session, "auto.held"), 0);
  EXPECT_GT(counter(session, "auto.analysis_rays"), 0);
  EXPECT_EQ(lightAutoSettings(*session.frame).neededResolution, atStart.neededResolution);

  // Playing, at a later pose: the choice made at `start` stands, no ray cast, no build; the
  // frustum fit follows the pose (the light has grown).
  session.playing = true;
  session.timelinePlaying = timelinePlaysLive(session, false);
  ASSERT_TRUE(session.timelinePlaying);
  ASSERT_EQ(session.setTime(later), "");
  run(session);
  EXPECT_EQ(counter(session, "auto.held"), 1);
  EXPECT_EQ(counter(session, "auto.analysis_rays"), 0);
  EXPECT_EQ(counter(session, "auto.bvh_builds"), 0);
  EXPECT_EQ(lightAutoSettings(*session.frame).neededResolution, atStart.neededResolution);
  EXPECT_EQ(counter(session, "auto.res_needed"), atStart.neededResolution);
  EXPECT_EQ(session.frame->light.mapSize, atStart.resolution);
  EXPECT_EQ(session.frame->light.layers, atStart.layers);
  ASSERT_FALSE(session.frame->autoReasons.empty());
  EXPECT_EQ(session.frame->autoReasons.front(), "auto: held while playing (decided at t = 0.25 s)");
  Scene posed = poseAt(animated, later);
  EXPECT_EQ(counter(session, "auto.fov_degrees"), fitLightFrustum(posed, 150).fovDegrees);
  EXPECT_FALSE(session.frame->timelinePlaying) << "the flag is the window run's only";

  // Paused at that pose: the same eye, pose and parameters, yet it runs again and decides as
  // the static scene at that pose does from scratch.
  session.playing = false;
  session.timelinePlaying = timelinePlaysLive(session, false);
  run(session);
  EXPECT_EQ(counter(session, "auto.held"), 0);
  EXPECT_GT(counter(session, "auto.analysis_rays"), 0);
  const AutoSettings& paused = lightAutoSettings(*session.frame);
  EXPECT_EQ(paused.resolution, atLater.resolution);
  EXPECT_EQ(paused.neededResolution, atLater.neededResolution);
  EXPECT_EQ(paused.layers, atLater.layers);
  EXPECT_EQ(paused.raysPerSide, atLater.raysPerSide);
  EXPECT_EQ(paused.smallestPenumbraWorld, atLater.smallestPenumbraWorld);  // bit for bit
  EXPECT_EQ(paused.reasons, atLater.reasons);
  EXPECT_EQ(session.frame->light.mapSize, atLater.resolution);
}

// A choice holds only for the eye size (and scene) it was made for; light.auto_while_playing
// = every_frame decides at every pose while playing.
TEST(WindowAutoHeld, ANewEyeOrEveryFrameDecidesAnew) {
  UiState state;
  useLightSweep(state, 160, 120);
  Session& session = state.session;
  run(session);  // decided at t = 0
  session.playing = true;
  session.timelinePlaying = true;
  ASSERT_EQ(session.setTime(1.0), "");
  run(session);
  EXPECT_EQ(counter(session, "auto.held"), 1);
  session.eye.width = 200;  // a new eye size while playing
  ASSERT_EQ(session.setTime(1.5), "");
  run(session);
  EXPECT_EQ(counter(session, "auto.held"), 0);
  EXPECT_GT(counter(session, "auto.analysis_rays"), 0);
  ASSERT_EQ(session.setTime(2.0), "");
  run(session);
  EXPECT_EQ(counter(session, "auto.held"), 1);
  ASSERT_EQ(session.frame->autoReasons.front(), "auto: held while playing (decided at t = 1.50 s)");

  ASSERT_EQ(session.setParameter("light.auto_while_playing", "every_frame"), "");
  ASSERT_EQ(session.setTime(2.5), "");
  run(session);
  EXPECT_EQ(counter(session, "auto.held"), 0);
  EXPECT_GT(counter(session, "auto.analysis_rays"), 0);
}

// Scripts (whose exports are of full-size frames at their own times) and runAll (every
// export) never hold, even while the timeline plays.
TEST(WindowAutoHeld, ScriptsAndExportsNeverHold) {
  UiState state;
  useLightSweep(state, 160, 120);
  Session& session = state.session;
  session.playing = true;
  EXPECT_TRUE(timelinePlaysLive(session, false));
  EXPECT_FALSE(timelinePlaysLive(session, true)) << "under a script";
  session.playing = false;
  EXPECT_FALSE(timelinePlaysLive(session, false)) << "paused";

  session.timelinePlaying = true;
  run(session);  // decided
  ASSERT_EQ(session.setTime(1.0), "");
  ASSERT_EQ(session.runAll(), "");
  EXPECT_EQ(counter(session, "auto.held"), 0);
  EXPECT_GT(counter(session, "auto.analysis_rays"), 0);
}

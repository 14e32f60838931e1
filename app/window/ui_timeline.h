// The timeline of an animated scene (scene/animation.h): play / pause, step, scrub, speed
// and the repeat mode, in a strip below the views (never over them) shown only while the
// scene is animated. The main
// loop advances the time while playing; every stage then runs on the new pose
// (Session::setTime).
#pragma once
#include <string>

struct Session;
class UiState;

// The wall clock of the last advance (seconds, steady clock; < 0: none yet).
struct TimelineClock {
  double last = -1;
};

// While playing: the session's time advanced by speed x the seconds since the last call.
// Returns "" or why the new pose was refused (playing then stops).
std::string advanceTimeline(Session& session, TimelineClock& clock, double nowSeconds);

// Whether the timeline plays live: playing an animated scene, not under a script (whose
// exports are of full-size frames at their own times) nor a recording (which stops play and
// sets each time itself). The main loop previews meanwhile, and the runs carry
// Frame::timelinePlaying, so `auto` keeps its last choices (light.auto_while_playing).
bool timelinePlaysLive(const Session& session, bool scripted);

// One frame step: 1/24 s, the frame rate of exported animations.
inline constexpr double kTimelineStep = 1.0 / 24;

// The height the timeline strip takes below the views: 0 for a static scene.
float timelineHeight(const Session& session);

// Draws the timeline strip at (x, y), width x height (nothing for a static scene).
// Returns "" or a refused pose.
std::string drawTimeline(UiState& state, float uiScale, float x, float y, float width, float height);

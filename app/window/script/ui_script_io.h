// What scripts and lessons hand the window frame by frame (one part of UiState,
// app/window/ui_state.h): screenshots to save, input to play as a user would, and the lesson
// panel's state. The actions themselves: app/window/script/ui_script_actions.cpp.
#pragma once
#include <array>
#include <deque>
#include <optional>
#include <string>

#include <glm/glm.hpp>

// One frame of mouse and modifier input that a script gives as a user would (ui_script.h
// "drag", "wheel"); window_app.cpp applies it over the backend's input before the UI frame.
struct SyntheticInput {
  glm::vec2 mouse{0, 0};  // window pixels
  std::array<bool, 3> buttons{false, false, false};  // left, right, middle
  bool alt = false, shift = false, ctrl = false;
  float wheel = 0;
};

struct ScriptIo {
  std::string screenshotRequest;  // saved at the end of this frame (script, key)
  std::optional<glm::vec2> cursorRequest;  // script: move the mouse here (window pixels)
  std::deque<SyntheticInput> syntheticInput;  // script: one entry per frame
  bool movesCamera = false;  // a script's "camera_moving": as if the mouse dragged
};

// The lesson being played (app/window/script/ui_lesson.h): what the panel shows.
struct LessonState {
  std::string title, text;  // the lesson's title; the current "say"
  int step = 0, steps = 0;  // "say" k of n
  bool waiting = false;     // interactive: the next step waits for the student
  bool next = false;        // the student asked for the next step
  bool finished = false;    // interactive: every step played; the window stays open
};

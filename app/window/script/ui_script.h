// `penumbra --script FILE`: a JSON list of UI actions run in order, then the window exits
// (for tests, reports and lesson figures). Each action is an object with one key:
//
//   {"select_stage": "hard_shadow"}          {"select_output": "light_layers.near"}
//   {"set": {"hard_shadow.offset": 0.01}}      {"pick": [x, y]}   (active view; row 0 at top)
//   {"select_ray": 3}                        {"wait": 2}        (frames)
//   {"export_view": "dir" | "f.png" | "f.exr"}   {"export_all": "dir"}
//   {"screenshot": "f.png"}                  {"view": 0 | 1}    (active view; 1 opens B)
//   {"two_views": true}   {"lock": true}     {"eye_size": [640, 480] | "fit"}
//   {"scene": "plate"}    {"colormap": "perceptual"}   {"channels": "G"}   {"level": 2}
//   {"range": [0, 1] | "autofit" | "reset"}  {"overlay": true}   {"zoom": 4 | "fit" | "1:1"}
//   {"camera_orbit": [yaw, pitch] (degrees)} {"camera_dolly": 0.8}
//   {"settings": {...settings JSON...}}      {"load_settings": "f.json"}
//   {"save_settings": "f.json"}              {"reload_shaders": true}   {"help": true}
//   {"run_every_frame": true}                {"print_timing": "label"}  (stdout)
//   {"print_pick": "label"}  (stdout: the pick's values in every output of its size, and
//                             the number of steps the ray trace panel shows)
//   {"compare_with_ground_truth": true}  (the pipeline panel's button: view B shows the
//                             error against the live ground truth, ui_live_truth.h)
//   {"print_truth": "label"} (stdout: the ground truth in use and why)
//   {"speed_error_measure": "minimal"} (the chart tab's "Measure this scene" with that
//                             preset; the script waits until the live run is done)
//   {"print_counters": "label"} (stdout: every counter of the last run, as the inspector)
//   {"camera_moving": true}  (as while dragging the camera: the preview resolution)
//   {"trace_window": true}   (the ray trace panel in its own large window)
//   {"mouse": [x, y]}        (moves the mouse there, window pixels: hover readouts)
// Input as a user gives it (app/window/script/ui_script_more.cpp), coordinates in image coordinates of the
// active view (row 0 at the top; may lie outside the image), over several frames:
//   {"drag": {"from": [x, y], "to": [x, y], "button": "left" | "right" | "middle",
//             "keys": "alt" | "alt+shift" | ..., "frames": 6}}
//   {"wheel": {"at": [x, y], "amount": 2, "keys": "alt"}}
// Views: {"difference": "light_layers.near" | ""} (active view shows output - that),
//   {"thickness": true} (light_layers.far - near, negative -> 0), {"clip_negative": true},
//   {"show_light": false} (the light outline over scene views)
//   {"show_ray": true} (nbuffer.levels in the active view, zoomed onto the picked ray's shapes)
// Lessons (`penumbra lesson`, docs/design.md#program): a lesson is a script with texts for
// the student:
//   {"lesson": "title"}  {"say": "text shown in the lesson panel and printed to stdout"}
//   {"export_dir": "name"} (relative export_view / export_all / screenshot paths go into
//                          that folder under the output folder; `--export DIR` overrides it;
//                          a lesson without either exports into the output folder under its
//                          file's name: app/window/script/ui_lesson_export.h)
//   {"export_view": {"file": "f.png", "caption": "... {ms:trace} ms", "annotate": true}}
//                          (a panel of the lesson's figure sheet, with its caption)
//   {"annotate": true}     (exported view PNGs carry a colour bar / legend and a caption)
//   {"crop": [x, y, w, h] | "none"} (exported panels hold only that rectangle; {crop.rmse},
//                          {crop.meanSigned}, ... are the error over it: ui_lesson_crop.h)
//   {"keep": {"rmse_a": "error.rmse"}}  (a number of this run, quoted later as {rmse_a};
//                          says and captions quote {ms:stage}, {ms}, {error.rmse}, ...)
//   {"collect": {"results": "{error.rmse}; "}} (appends the text, numbers filled, to what is
//                          kept as {results})
//   {"for_each_method": [actions]} (the actions once per shadow method of the registry, with
//                          {method}, {method.output}, {method.section}, {method.letter} and
//                          {method.stages} filled in: ui_script_actions.h)
// Played interactively (`penumbra lesson FILE` without --export), each "say" after the first
// waits for the student's "Next" (button, Space or N), and the window stays open at the end.
//
// The actions, their checks and handlers are one table: app/window/script/ui_script_actions.h.
// The whole file is checked before the window opens (names, argument types); actions that
// fail while running (an unknown output, a value out of range) stop the script. Either way
// the message names the action and what is valid, and penumbra exits with status 2.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "window/script/ui_script_actions.h"

class UiState;

struct ScriptAction {
  size_t index;  // 1-based position in the file, for messages
  std::string name;
  nlohmann::json argument;
};

// 1. Reads and checks a script file; "" or the message.
std::string parseScriptFile(const std::string& path, std::vector<ScriptAction>& actions);
std::string parseScriptJson(const nlohmann::json& root, std::vector<ScriptAction>& actions);

struct ScriptOptions {
  bool interactive = false;    // a lesson played by a student: wait for "Next" at each "say"
  std::string exportOverride;  // --export DIR: replaces the script's "export_dir"
  std::string path;            // the script's file: a lesson's default export folder
};

// 1b. The output rule for the script's files (README "Scripts and lessons"): "" or the
// message. Paths never hold ".."; with an export folder (--export, export_dir, a lesson's
// own) they are relative to it; a lesson's folder must be new, empty or an earlier export
// of a lesson (lesson.md), as it is replaced as a whole.
std::string checkScriptOutputs(const std::vector<ScriptAction>& actions, const ScriptOptions& options);

// 2. Runs actions frame by frame.
class ScriptRunner {
public:
  enum class Step { Running, Done, Failed };
  explicit ScriptRunner(std::vector<ScriptAction> actions, ScriptOptions options = {});
  // Runs actions until one needs frames to pass (wait, screenshot) or the list ends.
  Step step(UiState& state);
  const std::string& error() const { return error_; }
  size_t done() const { return next_; }  // actions started (progress: ui_export_progress.h)
  size_t total() const { return actions_.size(); }

private:
  bool waitForNext(UiState& state);  // interactive lessons: true while the student reads
  std::vector<ScriptAction> actions_;
  ScriptContext context_;
  size_t next_ = 0;
  bool finished_ = false;
  std::string error_;
};

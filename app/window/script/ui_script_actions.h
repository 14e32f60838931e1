// The script actions in one table (app/window/script/ui_script_actions.cpp): each row is a
// name, the check of its argument (run before the window opens) and its handler (the same
// state change a click makes). The runner (ui_script.h) only looks rows up.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "figures/figure_sheet.h"
#include "io/output_path.h"
#include "window/panels/ui_export.h"

class Pipeline;
class UiState;

// What a handler may change besides the window's state: the runner's own progress.
struct ScriptContext {
  int waitFrames = 0;             // frames still to wait ("wait")
  bool waitForSpeedError = false;  // "speed_error_measure": wait until the live run is done
  std::string pendingScreenshot;  // taken one frame later: new windows size themselves first
  std::string exportDirectory;    // relative export / screenshot paths go here
  bool exportOverridden = false;  // --export DIR replaces the script's "export_dir"
  bool interactive = false;       // a lesson played by a student
  int says = 0, saysSeen = 0;     // the lesson's "say" actions: in all, and so far
  bool annotate = false;          // "annotate": exported PNGs carry a colour bar and caption
  ImageRect crop;                 // "crop": exported panels and {crop.*} numbers (ui_lesson_crop.h)
  // A lesson's record (ui_lesson_export.h): its title, what it said (numbers filled in) and
  // the panels it exported, for the figure sheet and lesson.md.
  std::string lessonTitle;
  std::vector<std::string> said;
  std::vector<FigurePanel> panels;
  std::map<std::string, std::string> kept;  // "keep": numbers under names, for later texts
  // "for_each_method": the actions it expanded to, which the runner runs next.
  std::vector<std::pair<std::string, nlohmann::json>> expanded;
  // The output rule (io/output_path.h): with an export directory, paths are relative to it
  // (absolute and ".." refused, InputError); a lesson's directory is one transaction,
  // opened at its first file and committed by finishLesson (ui_lesson_export.h).
  bool transactional = false;  // a lesson: the export directory is replaced as a whole
  std::shared_ptr<DirectoryTransaction> transaction;
  std::string resolved(const std::string& path);
  // `text` with the transaction's temporary directory named as its target (messages).
  std::string shown(const std::string& text) const;
};

// A lesson's export folder is recognised as one by this file, written last.
inline constexpr const char* kLessonManifest = "lesson.md";
// A path a script writes: checkScriptPath (io/output_path.h).

using ScriptCheck = std::function<std::string(const nlohmann::json&)>;  // "" or what was expected
using ScriptHandler =
    std::function<std::string(UiState&, const nlohmann::json&, ScriptContext&)>;  // "" or why not

struct ScriptActionSpec {
  std::string name;
  ScriptCheck check;
  ScriptHandler run;
  bool newFrame = false;  // the next action waits a frame: it sees the new layout
};

const std::vector<ScriptActionSpec>& scriptActions();  // sorted by name
const ScriptActionSpec* findScriptAction(const std::string& name);
std::string scriptActionNames();  // "camera_dolly, camera_moving, ..."

// Handlers longer than a line, on input, views and lessons (ui_script_more.cpp).
std::string queueDrag(UiState& state, const nlohmann::json& a);
std::string queueWheel(UiState& state, const nlohmann::json& a);
std::string zoomActiveView(UiState& state, const nlohmann::json& a);
std::string showRay(UiState& state, const nlohmann::json& a);
std::string startLesson(UiState& state, const nlohmann::json& a, ScriptContext& context);
std::string say(UiState& state, const nlohmann::json& a, ScriptContext& context);
std::string exportView(UiState& state, const nlohmann::json& a, ScriptContext& context);
void printPick(const UiState& state, const std::string& label);
void printTiming(const UiState& state, const std::string& label);
std::string frameLoadedScene(UiState& state);
std::string collectText(const UiState& state, const nlohmann::json& a, ScriptContext& context);

// "for_each_method": a list of actions played once per shadow method of the pipeline, in
// registry order (Pipeline::methods(): the stages whose output carries kRoleShadowMethod), so
// a lesson over every method lists none by hand. In every string and key of the actions:
//   {method}          the stage ("filter")     {method.output}  its visibility ("filter.visibility")
//   {method.section}  its thesisSection()      {method.letter}  a, b, c, ... (the method's place)
//   {method.stages}   the stages its visibility depends on now, less those every method
//                     depends on (the G-buffer, the light), "+"-joined: "{ms:{method.stages}}"
// The check: a non-empty list of actions, each valid as written, none a lesson, say,
// export_dir or for_each_method, and no other {method...} placeholder.
std::string checkForEachMethod(const nlohmann::json& actions);
std::vector<std::pair<std::string, nlohmann::json>> expandForEachMethod(const Pipeline& pipeline,
                                                                      const nlohmann::json& actions);

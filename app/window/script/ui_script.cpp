#include "window/script/ui_script.h"

#include <cstdio>
#include <filesystem>

#include "base/input_error.h"
#include "base/json_input.h"

#include "window/panels/ui_speed_error.h"
#include "window/script/ui_lesson_export.h"
#include "window/ui_state.h"

using nlohmann::json;

namespace {

std::string describe(const ScriptAction& action) {
  return "script action " + std::to_string(action.index) + " (" + action.name + ")";
}

}  // namespace

// 1. Reading: the file under the limits every JSON input shares (base/json_input.h: a
// regular file, depth, size, string length, no repeated key), then every action checked
// against its row of the table (ui_script_actions.h): a list of one-key objects with
// arguments of the right shape and range. Messages: "<pointer>: script action N (name): ..."
// with the names and values cut.
std::string parseScriptJson(const json& root, std::vector<ScriptAction>& actions) {
  actions.clear();
  if (!root.is_array()) return "/: a script is a JSON list of actions, e.g. [{\"wait\": 1}]";
  for (size_t i = 0; i < root.size(); ++i) {
    const json& item = root[i];
    const std::string where = "/" + std::to_string(i) + ": script action " + std::to_string(i + 1);
    if (!item.is_object() || item.size() != 1)
      return where + ": expected an object with one key (the action), got " + shortJson(item);
    const std::string name = item.begin().key();
    const ScriptActionSpec* spec = findScriptAction(name);
    if (!spec)
      return where + ": unknown action '" + printable(name) + "'; valid actions: " + scriptActionNames();
    if (std::string problem = spec->check(item.begin().value()); !problem.empty())
      return jsonPointer("/" + std::to_string(i), name) + ": script action " + std::to_string(i + 1) +
             " (" + name + "): " + problem + ", got " + shortJson(item.begin().value());
    actions.push_back({i + 1, name, item.begin().value()});
  }
  return "";
}

std::string parseScriptFile(const std::string& path, std::vector<ScriptAction>& actions) {
  try {
    const std::string problem = parseScriptJson(readJsonFile(path), actions);
    return problem.empty() ? "" : printable(path, 200) + ": " + problem;
  } catch (const InputError& error) {
    return error.what();
  }
}

// 2. Stepping: a wait or a screenshot ends this frame's actions.
ScriptRunner::ScriptRunner(std::vector<ScriptAction> actions, ScriptOptions options)
    : actions_(std::move(actions)) {
  context_.exportDirectory = options.exportOverride;
  context_.exportOverridden = !options.exportOverride.empty();
  context_.interactive = options.interactive;
  bool lesson = false;
  for (const ScriptAction& action : actions_) {
    context_.says += action.name == "say";
    lesson = lesson || action.name == "lesson";
  }
  if (lesson && !context_.exportOverridden) context_.exportDirectory = defaultLessonDirectory(options.path);
  context_.transactional = lesson;  // a lesson's folder is written as one transaction
}

// Where a script's files go, known before the window opens: every path action checked
// against the output rule, and a lesson's folder (replaced as a whole) checked as a
// directory we may replace.
std::string checkScriptOutputs(const std::vector<ScriptAction>& written, const ScriptOptions& options) {
  // The actions of a for_each_method are checked as written (placeholders in their paths).
  std::vector<ScriptAction> actions;
  for (const ScriptAction& action : written) {
    actions.push_back(action);
    if (action.name == "for_each_method" && action.argument.is_array())
      for (const auto& item : action.argument)
        if (item.is_object() && item.size() == 1)
          actions.push_back({action.index, item.begin().key(), item.begin().value()});
  }
  bool lesson = false;
  std::string directory = options.exportOverride;
  for (const ScriptAction& action : actions) {
    lesson = lesson || action.name == "lesson";
    if (action.name == "export_dir" && options.exportOverride.empty())
      directory = (std::filesystem::path(kDefaultExportDirectory) / action.argument.get<std::string>()).string();
  }
  if (lesson && directory.empty()) directory = defaultLessonDirectory(options.path);
  for (const ScriptAction& action : actions) {
    const bool writes = action.name == "export_view" || action.name == "export_all" ||
                        action.name == "screenshot" || action.name == "save_settings";
    if (!writes) continue;
    const json& a = action.argument;
    const std::string path = a.is_string() ? a.get<std::string>() : a.value("file", std::string());
    if (std::string problem = checkScriptPath(path, !directory.empty()); !problem.empty())
      return "/" + std::to_string(action.index - 1) + "/" + action.name + ": script action " +
             std::to_string(action.index) + " (" + action.name + "): '" + printable(path, 200) + "': " + problem;
  }
  try {
    if (lesson) checkOutputDirectory(directory, "the lesson's export folder", kLessonManifest);
    else if (!directory.empty()) checkOutputDirectory(directory, "the export folder", "");
    // Outside a lesson's fresh folder, an export_all target that exists now is checked now
    // (it is checked again when the action runs).
    if (!lesson)
      for (const ScriptAction& action : actions)
        if (action.name == "export_all")
          checkOutputDirectory(std::filesystem::path(directory) / action.argument.get<std::string>(),
                               "script action " + std::to_string(action.index) + " (export_all)", "run.json");
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

ScriptRunner::Step ScriptRunner::step(UiState& state) {
  if (!error_.empty()) return Step::Failed;
  if (!state.script.syntheticInput.empty()) return Step::Running;  // a drag or wheel still playing
  if (!context_.pendingScreenshot.empty()) {
    state.script.screenshotRequest = context_.pendingScreenshot;
    context_.pendingScreenshot.clear();
    return Step::Running;
  }
  if (context_.waitFrames > 0) {
    --context_.waitFrames;
    return Step::Running;
  }
  if (context_.waitForSpeedError) {
    if (speedErrorRunning(state)) return Step::Running;  // the live run steps once per frame
    context_.waitForSpeedError = false;
    std::printf("penumbra: speed vs error: %d configurations measured\n", speedErrorPoints(state));
    std::fflush(stdout);
  }
  if (waitForNext(state)) return Step::Running;
  while (next_ < actions_.size()) {
    const ScriptAction action = actions_[next_++];  // a copy: for_each_method inserts
    const ScriptActionSpec* spec = findScriptAction(action.name);  // checked when parsed
    std::string problem;
    try {
      problem = spec ? spec->run(state, action.argument, context_) : "not implemented";
    } catch (const std::exception& error) {  // a path refused, a folder that cannot be made
      problem = error.what();
    }
    if (!problem.empty()) {
      error_ = describe(action) + ": " + printable(problem, 1000);
      return Step::Failed;
    }
    // A for_each_method's actions run next, under its number in messages.
    std::vector<ScriptAction> expanded;
    for (auto& [name, argument] : context_.expanded) expanded.push_back({action.index, name, std::move(argument)});
    context_.expanded.clear();
    actions_.insert(actions_.begin() + std::ptrdiff_t(next_), expanded.begin(), expanded.end());
    if (context_.waitFrames > 0) {
      --context_.waitFrames;  // this frame is the first waited one
      return Step::Running;
    }
    if (!context_.pendingScreenshot.empty()) return Step::Running;
    // The next action sees the re-run pipeline and the new layout.
    if (!state.script.syntheticInput.empty() || waitForNext(state)) return Step::Running;
    if (state.needsRun() || spec->newFrame) return Step::Running;
  }
  if (!finished_) {  // a lesson's figure sheet and text, once
    finished_ = true;
    std::string problem;
    try {
      problem = finishLesson(context_);
    } catch (const std::exception& error) {
      problem = error.what();
    }
    if (!problem.empty()) {
      error_ = problem;
      return Step::Failed;
    }
  }
  return Step::Done;
}

// 3. An interactive lesson holds each "say" after the first until the student asks for it.
bool ScriptRunner::waitForNext(UiState& state) {
  if (!context_.interactive || context_.saysSeen == 0 || next_ >= actions_.size() ||
      actions_[next_].name != "say" || state.lesson.next)
    return false;
  state.lesson.waiting = true;
  return true;
}

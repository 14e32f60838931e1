#include "window/script/ui_script.h"

#include <cstdio>
#include <fstream>

#include "window/panels/ui_speed_error.h"
#include "window/script/ui_lesson_export.h"
#include "window/ui_state.h"

using nlohmann::json;

namespace {

std::string describe(const ScriptAction& action) {
  return "script action " + std::to_string(action.index) + " (" + action.name + ")";
}

}  // namespace

// 1. Reading: every action is checked against its row of the table (ui_script_actions.h).
// A list of one-key objects with arguments of the right shape.
std::string parseScriptJson(const json& root, std::vector<ScriptAction>& actions) {
  actions.clear();
  if (!root.is_array()) return "a script is a JSON list of actions, e.g. [{\"wait\": 1}]";
  for (size_t i = 0; i < root.size(); ++i) {
    const json& item = root[i];
    const std::string where = "script action " + std::to_string(i + 1);
    if (!item.is_object() || item.size() != 1)
      return where + ": expected an object with one key (the action), got " + item.dump();
    const std::string name = item.begin().key();
    const ScriptActionSpec* spec = findScriptAction(name);
    if (!spec)
      return where + ": unknown action '" + name + "'; valid actions: " + scriptActionNames();
    if (std::string problem = spec->check(item.begin().value()); !problem.empty())
      return where + " (" + name + "): " + problem + ", got " + item.begin().value().dump();
    actions.push_back({i + 1, name, item.begin().value()});
  }
  return "";
}

std::string parseScriptFile(const std::string& path, std::vector<ScriptAction>& actions) {
  std::ifstream in(path);
  if (!in) return "cannot read script " + path;
  try {
    const std::string problem = parseScriptJson(json::parse(in), actions);
    return problem.empty() ? "" : path + ": " + problem;
  } catch (const json::parse_error& error) {
    return path + ": not valid JSON: " + error.what();
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
    if (speedErrorRunning()) return Step::Running;  // the live run steps once per frame
    context_.waitForSpeedError = false;
    std::printf("penumbra: speed vs error: %d configurations measured\n", speedErrorPoints());
    std::fflush(stdout);
  }
  if (waitForNext(state)) return Step::Running;
  while (next_ < actions_.size()) {
    const ScriptAction& action = actions_[next_++];
    const ScriptActionSpec* spec = findScriptAction(action.name);  // checked when parsed
    if (std::string problem = spec ? spec->run(state, action.argument, context_) : "not implemented";
        !problem.empty()) {
      error_ = describe(action) + ": " + problem;
      return Step::Failed;
    }
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
    if (std::string problem = finishLesson(context_); !problem.empty()) {
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

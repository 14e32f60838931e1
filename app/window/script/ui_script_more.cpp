// Script actions beyond the basic ones (app/window/script/ui_script.h): input as a user gives it (drag,
// wheel), difference views, the light outline, and lessons (lesson, say, export_dir).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "window/script/ui_script.h"
#include "window/ui_graph.h"
#include "window/ui_state.h"
#include "window/views/ui_view_difference.h"

using nlohmann::json;

namespace {

// 1. Arguments of drag and wheel.
bool readPoint(const json& value, glm::vec2& point) {
  if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number())
    return false;
  point = {value[0].get<float>(), value[1].get<float>()};
  return true;
}

std::string readKeys(const json& object, SyntheticInput& input) {
  if (!object.contains("keys")) return "";
  if (!object["keys"].is_string()) return "\"keys\": expected a string such as \"alt+shift\"";
  std::string keys = object["keys"].get<std::string>() + "+";
  for (size_t start = 0, plus; (plus = keys.find('+', start)) != std::string::npos; start = plus + 1) {
    const std::string key = keys.substr(start, plus - start);
    if (key == "alt") input.alt = true;
    else if (key == "shift") input.shift = true;
    else if (key == "ctrl") input.ctrl = true;
    else if (!key.empty()) return "\"keys\": unknown key '" + key + "'; valid: alt, shift, ctrl";
  }
  return "";
}

// Image coordinates of the active view (row 0 at the top, texel centres at +0.5) -> window
// pixels through the view's current zoom and pan.
glm::vec2 windowPoint(const UiState& state, const ViewPanel& view, glm::vec2 image) {
  const GlTexture* texture = shownTexture(state, view);
  const float height = texture ? float(texture->height()) : 0.0f;
  const glm::vec2 texel{image.x, height - image.y};
  return view.transform.screenFromTexel(texel, view.regionOrigin, view.regionSize);
}

std::string queueDrag(UiState& state, const json& a) {
  glm::vec2 from, to;
  if (!readPoint(a.value("from", json()), from) || !readPoint(a.value("to", json()), to))
    return "expected {\"from\": [x, y], \"to\": [x, y], ...} in image coordinates";
  SyntheticInput held;
  if (std::string problem = readKeys(a, held); !problem.empty()) return problem;
  const std::string button = a.value("button", std::string("left"));
  const int index = button == "left" ? 0 : button == "right" ? 1 : button == "middle" ? 2 : -1;
  if (index < 0) return "\"button\": expected left, right or middle";
  const int frames = std::clamp(a.value("frames", 6), 1, 240);
  const ViewPanel& view = state.views.panels[state.views.activeView];
  const glm::vec2 start = windowPoint(state, view, from), end = windowPoint(state, view, to);
  // Hover first (no jump counted as motion), press, move, release, then let go of the keys.
  SyntheticInput frame = held;
  frame.mouse = start;
  state.script.syntheticInput.push_back(frame);
  frame.buttons[size_t(index)] = true;
  state.script.syntheticInput.push_back(frame);
  for (int i = 1; i <= frames; ++i) {
    frame.mouse = start + (end - start) * (float(i) / float(frames));
    state.script.syntheticInput.push_back(frame);
  }
  frame.buttons[size_t(index)] = false;
  state.script.syntheticInput.push_back(frame);
  state.script.syntheticInput.push_back({frame.mouse});
  return "";
}

std::string queueWheel(UiState& state, const json& a) {
  glm::vec2 at;
  if (!readPoint(a.value("at", json()), at) || !a.value("amount", json()).is_number())
    return "expected {\"at\": [x, y], \"amount\": n, \"keys\": ...} in image coordinates";
  SyntheticInput frame;
  if (std::string problem = readKeys(a, frame); !problem.empty()) return problem;
  frame.mouse = windowPoint(state, state.views.panels[state.views.activeView], at);
  state.script.syntheticInput.push_back(frame);  // hover
  frame.wheel = a["amount"].get<float>();
  state.script.syntheticInput.push_back(frame);
  state.script.syntheticInput.push_back({frame.mouse});
  return "";
}

}  // namespace

// 2. Paths: relative targets go into the export directory (the script's or --export's).
std::string ScriptRunner::resolved(const std::string& path) const {
  if (exportDirectory_.empty() || std::filesystem::path(path).is_absolute()) return path;
  return (std::filesystem::path(exportDirectory_) / path).string();
}

// 3. An interactive lesson holds each "say" after the first until the student asks for it.
bool ScriptRunner::waitForNext(UiState& state) {
  if (!options_.interactive || saysSeen_ == 0 || next_ >= actions_.size() ||
      actions_[next_].name != "say" || state.lesson.next)
    return false;
  state.lesson.waiting = true;
  return true;
}

// 4. The actions.
std::string ScriptRunner::runMore(UiState& state, const ScriptAction& action) {
  const json& a = action.argument;
  const std::string& name = action.name;
  ViewPanel& view = state.views.panels[state.views.activeView];
  if (name == "drag") return queueDrag(state, a);
  if (name == "wheel") return queueWheel(state, a);
  if (name == "difference") return setViewDifference(state, view, a.get<std::string>());
  if (name == "thickness") return a.get<bool>() ? showThickness(state) : setViewDifference(state, view, "");
  if (name == "clip_negative") { view.clipNegative = a.get<bool>(); return ""; }
  if (name == "show_light") { state.views.showLight = a.get<bool>(); return ""; }
  if (name == "show_ray") {  // as the trace panel's "Show on N-buffer" button
    ViewPanel* target = state.views.selectionTarget();
    const std::string levels = recordingInput(state.session.pipeline, "levels");
    if (levels.empty()) return "no stage records rays over an N-buffer (levels slot)";
    if (std::string problem = state.selectOutput(levels); !problem.empty()) return problem;
    if (target) target->frameOverlays = a.get<bool>();
    return "";
  }
  if (name == "lesson") {
    state.lesson.title = a.get<std::string>();
    state.lesson.steps = says_;
    std::printf("lesson: %s\n", state.lesson.title.c_str());
    std::fflush(stdout);
    return "";
  }
  if (name == "say") {
    state.lesson.text = a.get<std::string>();
    state.lesson.step = ++saysSeen_;
    state.lesson.steps = says_;
    state.lesson.next = state.lesson.waiting = false;
    std::printf("lesson step %d/%d: %s\n", saysSeen_, says_, state.lesson.text.c_str());
    std::fflush(stdout);
    return "";
  }
  if (name == "export_dir") {
    if (options_.exportOverride.empty()) exportDirectory_ = a.get<std::string>();
    return "";
  }
  return "not implemented";
}

// Script handlers longer than a line (the table: ui_script_actions.cpp): input as a user
// gives it (drag, wheel), zoom, the ray on the N-buffer, lessons, and the printed readouts.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "scene/scene_frame.h"
#include "base/input_error.h"
#include "base/json_input.h"
#include "window/script/ui_lesson_export.h"
#include "window/script/ui_script_actions.h"
#include "window/ui_graph.h"
#include "window/ui_state.h"
#include "window/views/ui_view_difference.h"

using nlohmann::json;

namespace {

// The lesson panel draws a text as one ImGui item: Dear ImGui's 16-bit vertex indices hold
// about 16,000 glyphs per draw call, so a text (numbers filled in) stays far below that.
constexpr size_t kMaxLessonText = 6000;

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
  for (size_t start = 0, plus; (plus = keys.find('+', start)) != std::string::npos;
       start = plus + 1) {
    const std::string key = keys.substr(start, plus - start);
    if (key == "alt")
      input.alt = true;
    else if (key == "shift")
      input.shift = true;
    else if (key == "ctrl")
      input.ctrl = true;
    else if (!key.empty())
      return "\"keys\": unknown key '" + key + "'; valid: alt, shift, ctrl";
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

}  // namespace

// 2. Input over several frames.
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

// 3. Zoom: "fit", "1:1", or a factor about what matters in the texture.
std::string zoomActiveView(UiState& state, const json& a) {
  ViewPanel& view = state.views.panels[state.views.activeView];
  if (a == "fit")
    view.fitPending = true;
  else if (a == "1:1") {
    view.transform.oneToOne();
    view.fitted = false;
  } else {
    // Settle a pending fit first, then zoom about the pick if it lies in this texture.
    const GlTexture* texture = shownTexture(state, view);
    if (texture && view.fitPending && view.regionSize.x > 0) {
      view.transform.fit({texture->width(), texture->height()}, view.regionSize);
      view.fitPending = false;
      view.lastTextureSize = {texture->width(), texture->height()};
    }
    view.transform.zoom = std::clamp(a.get<float>(), kMinZoom, kMaxZoom);
    view.fitted = false;
    // Centre on what matters in this texture: the ray's visited windows, else the pick.
    const glm::ivec2 size =
        texture ? glm::ivec2(texture->width(), texture->height()) : glm::ivec2(0);
    if (texture && state.views.pick && state.views.pickSpace == size)
      view.transform.center = glm::vec2(*state.views.pick) + 0.5f;
    glm::vec2 lo{1e30f}, hi{-1e30f};
    for (const ViewOverlayShape& shape : state.views.overlays)
      if (shape.space == size && !shape.line) {  // windows and dots
        lo = glm::min(lo, glm::min(shape.a, shape.b));
        hi = glm::max(hi, glm::max(shape.a, shape.b));
      }
    if (lo.x <= hi.x) view.transform.center = 0.5f * (lo + hi);
    if (state.views.linked) state.views.linkFrom(state.views.activeView);
  }
  return "";
}

// 4. As the trace panel's "Show on N-buffer" (min-max mipmap: "Show on near layer") button.
std::string showRay(UiState& state, const json& a) {
  ViewPanel* target = state.views.selectionTarget();
  const RayOverlayTarget shown = rayOverlayTarget(state.session.pipeline, state.session.frame.get());
  if (shown.output.empty()) return "no stage records rays over a hierarchy (levels slot)";
  if (std::string problem = state.selectOutput(shown.output); !problem.empty()) return problem;
  if (target) target->frameOverlays = a.get<bool>();
  return "";
}

// 5. Lessons: the title and each "say" for the lesson panel and stdout.
std::string startLesson(UiState& state, const json& a, ScriptContext& context) {
  // Texts from the file reach the terminal and the lesson panel: no control characters
  // (an ESC or BEL would act on the terminal), bounded (base/json_input.h).
  state.lesson.title = context.lessonTitle = plainText(a.get<std::string>(), 200);
  state.lesson.steps = context.says;
  std::printf("lesson: %s\n", state.lesson.title.c_str());
  std::fflush(stdout);
  return "";
}

std::string say(UiState& state, const json& a, ScriptContext& context) {
  std::string problem;
  state.lesson.text = plainText(fillNumbers(state, context, a.get<std::string>(), problem), kMaxLessonText);
  if (!problem.empty()) return problem;
  context.said.push_back(state.lesson.text);
  state.lesson.step = ++context.saysSeen;
  state.lesson.steps = context.says;
  state.lesson.next = state.lesson.waiting = false;
  std::printf("lesson step %d/%d: %s\n", context.saysSeen, context.says, state.lesson.text.c_str());
  std::fflush(stdout);
  return "";
}

// 6. Readouts on stdout.
// The pick's raw values in every output of its size, and the trace panel's step count.
void printPick(const UiState& state, const std::string& label) {
  if (!state.views.pick) {
    std::printf("pick %s: none\n", label.c_str());
    return;
  }
  const glm::ivec2 pick = *state.views.pick;
  std::printf("pick %s: (%d, %d) in %dx%d\n", label.c_str(), pick.x,
              state.views.pickSpace.y - 1 - pick.y, state.views.pickSpace.x,
              state.views.pickSpace.y);
  for (const std::string& key : state.session.outputKeys()) {
    if (!state.session.frame->has(key)) continue;
    const GlTexture& texture = state.session.frame->texture(key);
    if (texture.width() != state.views.pickSpace.x || texture.height() != state.views.pickSpace.y)
      continue;
    const auto texel = readTexel(texture, pick.x, pick.y, 0);
    std::printf("  %s", key.c_str());
    for (int c = 0; c < texture.channelCount(); ++c) std::printf(" %.9g", texel[size_t(c)]);
    std::printf("\n");
  }
  if (state.views.traceSource) {
    const RayTraceInfo trace =
        state.views.traceSource(*state.session.frame, pick, state.views.selectedRay);
    int samples = 0, refinements = 0;
    for (const RayStepRecord& step : trace.steps) {
      samples += step.point && !step.refinement;
      refinements += step.refinement;
    }
    std::printf(
        "  trace steps: %zu (ray %d of %d) %s\n  trace points: %d samples, %d refinements\n",
        trace.steps.size(), state.views.selectedRay, trace.raysPerPixel, trace.result.c_str(),
        samples, refinements);
  }
  std::fflush(stdout);
}

// Per stage: the last run and the median over the runs with identical settings.
void printTiming(const UiState& state, const std::string& label) {
  std::printf(
      "timing %s: eye %dx%d, pipeline median %.2f ms (%.1f runs/s) over %d runs, last "
      "run %.2f ms, UI %.1f fps, %d pipeline runs in this window\n",
      label.c_str(), state.session.frame->eyeWidth, state.session.frame->eyeHeight,
      state.session.medianPipelineMs(),
      state.session.medianPipelineMs() > 0 ? 1000.0 / state.session.medianPipelineMs() : 0.0,
      state.session.medianRuns(), state.session.lastPipelineMs(), state.session.framesPerSecond(),
      state.session.pipelineRuns);
  for (const StageTime& time : state.session.pipeline.lastTimes())
    if (time.ran)
      std::printf("  %-14s %8.2f ms (last %.2f ms, %d runs)\n", time.stage.c_str(), time.median,
                  time.milliseconds, time.runs);
    else
      std::printf("  %-14s  not run\n", time.stage.c_str());
  std::fflush(stdout);
}

// 5. The camera, the ground and the light fitted to the loaded model (the scene panel's
//    "Frame scene" button and the frame_scene action): a copy is framed and adopted, so the
//    GPU scene is rebuilt with the moved ground and "Reset camera" returns to the framing.
//    An animated scene is framed at rest and keeps its animation and its time.
std::string frameLoadedScene(UiState& state) {
  const bool animated = state.session.animated();
  const double time = state.session.time;
  Scene framed = animated ? state.session.rest : state.session.scene;
  frameScene(framed);
  if (std::string problem = validateScene(framed); !problem.empty()) return "frame scene: " + problem;
  const std::string source = state.session.sceneSource;
  state.adoptScene(std::move(framed), source);
  if (animated)
    if (std::string problem = state.session.setTime(time); !problem.empty()) return "frame scene: " + problem;
  state.status = "framed: " + boundsText(framedBounds(state.session.scene));
  return "";
}

// 6. "collect": {"name": "text"} appends the text, its numbers filled in, to what is kept
//    under the name (empty at first), so a later text quotes every pass of a
//    for_each_method as {name}.
std::string collectText(const UiState& state, const json& a, ScriptContext& context) {
  for (const auto& [name, text] : a.items()) {
    if (!text.is_string()) return "\"" + printable(name, 80) + "\": expected a text such as \"{error.rmse}; \"";
    std::string problem;
    const std::string filled = fillNumbers(state, context, text.get<std::string>(), problem);
    if (!problem.empty()) return problem;
    if (context.kept[name].size() + filled.size() > kMaxLessonText)
      return "\"" + printable(name, 80) + "\": the collected text exceeds " + std::to_string(kMaxLessonText) + " characters";
    context.kept[name] += filled;
  }
  return "";
}

// 7. for_each_method (ui_script_actions.h): the placeholders of one method, filled in every
//    string and key of the actions.
namespace {

const char* const kMethodPlaceholders[] = {"{method}", "{method.output}", "{method.section}",
                                           "{method.letter}", "{method.stages}"};
// A lesson counts its says before it runs (its steps), and has one title and one folder.
const char* const kForbiddenInLoop[] = {"for_each_method", "lesson", "export_dir", "say"};

// The first "{method...}" in `text` that is not a placeholder; "" if none.
std::string unknownPlaceholder(const std::string& text) {
  for (size_t at = text.find("{method"); at != std::string::npos; at = text.find("{method", at + 1)) {
    const size_t close = text.find('}', at);
    const std::string token = close == std::string::npos ? text.substr(at) : text.substr(at, close - at + 1);
    bool known = false;
    for (const char* placeholder : kMethodPlaceholders) known |= token == placeholder;
    if (!known) return token;
  }
  return "";
}

std::string unknownPlaceholderIn(const json& value) {
  if (value.is_string()) return unknownPlaceholder(value.get<std::string>());
  if (value.is_object())
    for (const auto& [key, item] : value.items()) {
      if (std::string token = unknownPlaceholder(key); !token.empty()) return token;
      if (std::string token = unknownPlaceholderIn(item); !token.empty()) return token;
    }
  if (value.is_array())
    for (const json& item : value)
      if (std::string token = unknownPlaceholderIn(item); !token.empty()) return token;
  return "";
}

std::string filled(std::string text, const std::vector<std::pair<std::string, std::string>>& values) {
  for (const auto& [placeholder, value] : values)
    for (size_t at = 0; (at = text.find(placeholder, at)) != std::string::npos; at += value.size())
      text.replace(at, placeholder.size(), value);
  return text;
}

json filledJson(const json& value, const std::vector<std::pair<std::string, std::string>>& values) {
  if (value.is_string()) return filled(value.get<std::string>(), values);
  if (value.is_object()) {
    json object = json::object();
    for (const auto& [key, item] : value.items()) object[filled(key, values)] = filledJson(item, values);
    return object;
  }
  if (value.is_array()) {
    json array = json::array();
    for (const json& item : value) array.push_back(filledJson(item, values));
    return array;
  }
  return value;
}

}  // namespace

std::string checkForEachMethod(const json& actions) {
  if (!actions.is_array() || actions.empty())
    return "expected a non-empty list of actions, played once per shadow method";
  for (size_t i = 0; i < actions.size(); ++i) {
    const json& item = actions[i];
    const std::string where = "action " + std::to_string(i + 1) + " of the list";
    if (!item.is_object() || item.size() != 1) return where + ": expected an object with one key (the action)";
    const std::string name = item.begin().key();
    for (const char* forbidden : kForbiddenInLoop)
      if (name == forbidden) return where + ": " + name + " cannot be played once per method";
    const ScriptActionSpec* spec = findScriptAction(name);
    if (!spec) return where + ": unknown action '" + printable(name, 80) + "'; valid actions: " + scriptActionNames();
    if (std::string problem = spec->check(item.begin().value()); !problem.empty())
      return where + " (" + name + "): " + problem;
    if (std::string token = unknownPlaceholderIn(item.begin().value()); !token.empty())
      return where + " (" + name + "): unknown placeholder '" + printable(token, 80) +
             "'; valid: {method}, {method.output}, {method.section}, {method.letter}, {method.stages}";
  }
  return "";
}

std::vector<std::pair<std::string, json>> expandForEachMethod(const Pipeline& pipeline, const json& actions) {
  const std::vector<std::string> methods = pipeline.methods();
  // The stages every method's visibility depends on (the G-buffer, the light) are shared
  // costs: {method.stages} leaves them out, except the method itself.
  std::map<std::string, std::vector<std::string>> dependsOn;
  std::map<std::string, size_t> uses;
  for (const std::string& method : methods) {
    dependsOn[method] = pipeline.dependencies({pipeline.methodOutput(method)});
    for (const std::string& stage : dependsOn[method]) ++uses[stage];
  }
  std::vector<std::pair<std::string, json>> expanded;
  for (size_t m = 0; m < methods.size(); ++m) {
    const std::string& method = methods[m];
    std::string stages;
    for (const std::string& stage : dependsOn[method])
      if (stage == method || uses[stage] < methods.size()) stages += (stages.empty() ? "" : "+") + stage;
    const std::vector<std::pair<std::string, std::string>> values = {
        {"{method.output}", pipeline.methodOutput(method)},
        {"{method.section}", pipeline.stage(method).thesisSection()},
        {"{method.letter}", std::string(1, char('a' + m % 26))},
        {"{method.stages}", stages},
        {"{method}", method}};
    for (const json& item : actions) expanded.emplace_back(item.begin().key(), filledJson(item.begin().value(), values));
  }
  return expanded;
}

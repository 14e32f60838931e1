#include "window/script/ui_script.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <set>

#include "window/ui_camera.h"
#include "window/panels/ui_export.h"
#include "window/script/ui_settings.h"
#include "window/ui_state.h"
#include "window/views/ui_view_toolbar.h"

using nlohmann::json;

namespace {

// 1. Argument shapes: each returns "" or what was expected.
using Check = std::function<std::string(const json&)>;

const Check kString = [](const json& v) { return v.is_string() ? "" : "expected a string"; };
const Check kObject = [](const json& v) { return v.is_object() ? "" : "expected an object"; };
const Check kBool = [](const json& v) { return v.is_boolean() ? "" : "expected true or false"; };
const Check kCount = [](const json& v) {
  return v.is_number_integer() && v.get<long long>() >= 0 ? "" : "expected an integer >= 0";
};
const Check kPair = [](const json& v) {
  return v.is_array() && v.size() == 2 && v[0].is_number() && v[1].is_number() ? ""
                                                                                : "expected [a, b]";
};
Check pairOr(std::initializer_list<const char*> words) {
  std::vector<std::string> allowed(words.begin(), words.end());
  return [allowed](const json& v) -> std::string {
    if (kPair(v).empty()) return "";
    for (const std::string& word : allowed)
      if (v == word) return "";
    std::string text = "expected [a, b]";
    for (const std::string& word : allowed) text += " or \"" + word + "\"";
    return text;
  };
}

const std::map<std::string, Check>& actionChecks() {
  static const std::map<std::string, Check> checks = {
      {"select_stage", kString}, {"select_output", kString}, {"set", kObject},
      {"pick", kPair}, {"select_ray", kCount}, {"wait", kCount}, {"export_view", kString},
      {"export_all", kString}, {"screenshot", kString}, {"view", kCount},
      {"two_views", kBool}, {"lock", kBool}, {"eye_size", pairOr({"fit"})}, {"scene", kString},
      {"colormap", kString}, {"channels", kString}, {"level", kCount},
      {"range", pairOr({"autofit", "reset"})}, {"overlay", kBool},
      {"zoom", [](const json& v) -> std::string {
         return (v.is_number() && v.get<double>() > 0) || v == "fit" || v == "1:1"
                    ? "" : "expected a zoom factor > 0, \"fit\" or \"1:1\"";
       }},
      {"camera_orbit", kPair},
      {"camera_dolly", [](const json& v) -> std::string {
         return v.is_number() && v.get<double>() > 0 ? "" : "expected a factor > 0";
       }},
      {"settings", kObject}, {"load_settings", kString}, {"save_settings", kString},
      {"reload_shaders", kBool}, {"help", kBool}, {"run_every_frame", kBool},
      {"print_timing", kString}, {"print_pick", kString}, {"camera_moving", kBool},
      {"trace_window", kBool}, {"mouse", kPair}, {"drag", kObject}, {"wheel", kObject},
      {"difference", kString}, {"thickness", kBool}, {"clip_negative", kBool},
      {"show_light", kBool}, {"show_ray", kBool}, {"lesson", kString}, {"say", kString}, {"export_dir", kString}};
  return checks;
}

std::string validNames() {
  std::string names;
  for (const auto& [name, check] : actionChecks()) names += (names.empty() ? "" : ", ") + name;
  return names;
}

std::string describe(const ScriptAction& action) {
  return "script action " + std::to_string(action.index) + " (" + action.name + ")";
}

}  // namespace

// 2. Parsing: a list of one-key objects with arguments of the right shape.
std::string parseScriptJson(const json& root, std::vector<ScriptAction>& actions) {
  actions.clear();
  if (!root.is_array()) return "a script is a JSON list of actions, e.g. [{\"wait\": 1}]";
  for (size_t i = 0; i < root.size(); ++i) {
    const json& item = root[i];
    const std::string where = "script action " + std::to_string(i + 1);
    if (!item.is_object() || item.size() != 1)
      return where + ": expected an object with one key (the action), got " + item.dump();
    const std::string name = item.begin().key();
    const auto check = actionChecks().find(name);
    if (check == actionChecks().end())
      return where + ": unknown action '" + name + "'; valid actions: " + validNames();
    if (std::string problem = check->second(item.begin().value()); !problem.empty())
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

// 3. Stepping: a wait or a screenshot ends this frame's actions.
ScriptRunner::ScriptRunner(std::vector<ScriptAction> actions, ScriptOptions options)
    : actions_(std::move(actions)), options_(std::move(options)),
      exportDirectory_(options_.exportOverride) {
  for (const ScriptAction& action : actions_) says_ += action.name == "say";
}

ScriptRunner::Step ScriptRunner::step(UiState& state) {
  if (!error_.empty()) return Step::Failed;
  if (!state.script.syntheticInput.empty()) return Step::Running;  // a drag or wheel still playing
  if (!pendingScreenshot_.empty()) {
    state.script.screenshotRequest = pendingScreenshot_;
    pendingScreenshot_.clear();
    return Step::Running;
  }
  if (waitFrames_ > 0) {
    --waitFrames_;
    return Step::Running;
  }
  if (waitForNext(state)) return Step::Running;
  while (next_ < actions_.size()) {
    const ScriptAction& action = actions_[next_++];
    if (std::string problem = run(state, action); !problem.empty()) {
      error_ = describe(action) + ": " + problem;
      return Step::Failed;
    }
    if (action.name == "wait" && waitFrames_ > 0) {
      --waitFrames_;  // this frame is the first waited one
      return Step::Running;
    }
    if (action.name == "screenshot") return Step::Running;
    // The next action sees the re-run pipeline and the new layout.
    if (!state.script.syntheticInput.empty() || waitForNext(state)) return Step::Running;
    static const std::set<std::string> layoutChanging = {
        "select_output", "select_stage", "two_views", "view", "help", "trace_window",
        "camera_moving", "difference", "thickness", "say", "lesson"};
    if (state.needsRun() || layoutChanging.count(action.name)) return Step::Running;
  }
  return Step::Done;
}

namespace {

const GlTexture* activeTexture(UiState& state) {
  return shownTexture(state, state.views.panels[state.views.activeView]);
}

// The pick's raw values in every output of its size, and the trace panel's step count.
void printPick(const UiState& state, const std::string& label) {
  if (!state.views.pick) {
    std::printf("pick %s: none\n", label.c_str());
    return;
  }
  const glm::ivec2 pick = *state.views.pick;
  std::printf("pick %s: (%d, %d) in %dx%d\n", label.c_str(), pick.x, state.views.pickSpace.y - 1 - pick.y,
              state.views.pickSpace.x, state.views.pickSpace.y);
  for (const std::string& key : state.session.outputKeys()) {
    if (!state.session.frame->has(key)) continue;
    const GlTexture& texture = state.session.frame->texture(key);
    if (texture.width() != state.views.pickSpace.x || texture.height() != state.views.pickSpace.y) continue;
    const auto texel = readTexel(texture, pick.x, pick.y, 0);
    std::printf("  %s", key.c_str());
    for (int c = 0; c < texture.channelCount(); ++c) std::printf(" %.9g", texel[size_t(c)]);
    std::printf("\n");
  }
  if (rayTraceSource()) {
    const RayTraceInfo trace = rayTraceSource()(*state.session.frame, pick, state.views.selectedRay);
    int samples = 0, refinements = 0;
    for (const RayStepRecord& step : trace.steps) {
      samples += step.point && !step.refinement;
      refinements += step.refinement;
    }
    std::printf("  trace steps: %zu (ray %d of %d) %s\n  trace points: %d samples, %d refinements\n",
                trace.steps.size(), state.views.selectedRay, trace.raysPerPixel, trace.result.c_str(),
                samples, refinements);
  }
  std::fflush(stdout);
}

// Per stage: the last run and the median over the runs with identical settings.
void printTiming(const UiState& state, const std::string& label) {
  std::printf("timing %s: eye %dx%d, pipeline median %.2f ms (%.1f runs/s) over %d runs, last "
              "run %.2f ms, UI %.1f fps\n",
              label.c_str(), state.session.frame->eyeWidth, state.session.frame->eyeHeight, state.session.medianPipelineMs(),
              state.session.medianPipelineMs() > 0 ? 1000.0 / state.session.medianPipelineMs() : 0.0,
              state.session.medianRuns(), state.session.lastPipelineMs(), state.session.framesPerSecond());
  for (const StageTime& time : state.session.pipeline.lastTimes())
    if (time.ran)
      std::printf("  %-14s %8.2f ms (last %.2f ms, %d runs)\n", time.stage.c_str(), time.median,
                  time.milliseconds, time.runs);
    else
      std::printf("  %-14s  not run\n", time.stage.c_str());
  std::fflush(stdout);
}

}  // namespace

// 4. One action: the same state changes a click makes.
std::string ScriptRunner::run(UiState& state, const ScriptAction& action) {
  const json& a = action.argument;
  const std::string& name = action.name;
  ViewPanel& view = state.views.panels[state.views.activeView];
  if (name == "select_stage") return state.selectStage(a.get<std::string>());
  if (name == "select_output") return state.selectOutput(a.get<std::string>());
  if (name == "set") {
    for (const auto& [key, value] : a.items()) {
      const std::string text = value.is_string() ? value.get<std::string>() : value.dump();
      if (std::string problem = state.session.setParameter(key, text); !problem.empty()) return problem;
    }
    return "";
  }
  if (name == "pick") {
    const GlTexture* texture = activeTexture(state);
    if (!texture) return "the active view shows no texture";
    // Image coordinates (row 0 at the top) -> GL texel (row 0 at the bottom).
    state.views.setPick({a[0].get<int>(), texture->height() - 1 - a[1].get<int>()},
                  {texture->width(), texture->height()});
    return "";
  }
  if (name == "select_ray") { state.views.selectedRay = a.get<int>(); return ""; }
  if (name == "wait") { waitFrames_ = a.get<int>(); return ""; }
  if (name == "export_view" || name == "export_all") {
    const std::string target = resolved(a.get<std::string>());
    state.status = name == "export_view" ? exportViewFiles(state, view, target, ExportKind::Both)
                                         : exportAllStages(state, target);
    std::printf("penumbra: %s\n", state.status.c_str());
    return state.status.rfind("wrote ", 0) == 0 ? "" : state.status;
  }
  if (name == "screenshot") { pendingScreenshot_ = resolved(a.get<std::string>()); return ""; }
  if (name == "view") {
    if (a.get<int>() > 1) return "views are 0 (A) and 1 (B)";
    state.views.activeView = a.get<int>();
    state.views.twoViews = state.views.twoViews || state.views.activeView == 1;
    return "";
  }
  if (name == "two_views") {
    state.views.twoViews = a.get<bool>();
    if (!state.views.twoViews) state.views.activeView = 0;
    return "";
  }
  if (name == "lock") { view.locked = a.get<bool>(); return ""; }
  if (name == "eye_size") {
    if (a == "fit") state.session.eye.fitView = true;
    else if (a[0].get<int>() < 16 || a[1].get<int>() < 16 || a[0].get<int>() > 8192 || a[1].get<int>() > 8192)
      return "sizes are in [16, 8192]";
    else state.session.eye = {false, a[0].get<int>(), a[1].get<int>()};
    return "";
  }
  if (name == "scene") return state.loadScene(a.get<std::string>());
  if (name == "colormap") {
    const auto names = colormapNames();
    for (size_t m = 0; m < names.size(); ++m)
      if (names[m] == a) { view.settings.colormap = Colormap(m); return ""; }
    return "unknown colormap; valid: gray, perceptual, diverging, categorical";
  }
  if (name == "channels") {
    const std::string letters = a.get<std::string>();
    if (letters.find_first_not_of("RGBA") != std::string::npos) return "expected letters from RGBA";
    for (int c = 0; c < 4; ++c) view.settings.channels[size_t(c)] = letters.find("RGBA"[c]) != std::string::npos;
    return "";
  }
  if (name == "level") { view.settings.layer = a.get<int>(); return ""; }
  if (name == "range") {
    const GlTexture* texture = activeTexture(state);
    if (a == "autofit") view.autofitPending = true;
    else if (a == "reset") { if (texture) resetView(state, view, *texture); }
    else { view.settings.black = a[0].get<float>(); view.settings.white = a[1].get<float>(); }
    return "";
  }
  if (name == "overlay") { view.settings.overlay = a.get<bool>(); return ""; }
  if (name == "zoom") {
    if (a == "fit") view.fitPending = true;
    else if (a == "1:1") {
      view.transform.oneToOne();
      view.fitted = false;
    }
    else {
      // Settle a pending fit first, then zoom about the pick if it lies in this texture.
      const GlTexture* texture = activeTexture(state);
      if (texture && view.fitPending && view.regionSize.x > 0) {
        view.transform.fit({texture->width(), texture->height()}, view.regionSize);
        view.fitPending = false;
        view.lastTextureSize = {texture->width(), texture->height()};
      }
      view.transform.zoom = std::clamp(a.get<float>(), kMinZoom, kMaxZoom);
      view.fitted = false;
      // Centre on what matters in this texture: the ray's visited windows, else the pick.
      const glm::ivec2 size = texture ? glm::ivec2(texture->width(), texture->height()) : glm::ivec2(0);
      if (texture && state.views.pick && state.views.pickSpace == size)
        view.transform.center = glm::vec2(*state.views.pick) + 0.5f;
      glm::vec2 lo{1e30f}, hi{-1e30f};
      for (const ViewOverlayShape& shape : state.views.overlays)
        if (shape.space == size && !shape.line) {  // windows and dots
          lo = glm::min(lo, glm::min(shape.a, shape.b));
          hi = glm::max(hi, glm::max(shape.a, shape.b));
        }
      if (lo.x <= hi.x) view.transform.center = 0.5f * (lo + hi);
    }
    return "";
  }
  if (name == "camera_orbit") {
    orbitCamera(state.session.scene.camera, glm::radians(a[0].get<float>()), glm::radians(a[1].get<float>()));
    return "";
  }
  if (name == "camera_dolly") { dollyCamera(state.session.scene.camera, a.get<float>()); return ""; }
  if (name == "settings") return applySettingsJson(state, a);
  if (name == "load_settings") {
    bool ok = false;
    state.status = loadSettingsFile(state, a.get<std::string>(), ok);
    return ok ? "" : state.status;
  }
  if (name == "save_settings") {
    state.status = saveSettingsFile(state, a.get<std::string>());
    return state.status.rfind("saved", 0) == 0 ? "" : state.status;
  }
  if (name == "reload_shaders") { state.reloadShaders(); return ""; }
  if (name == "help") { state.showHelp = a.get<bool>(); return ""; }
  if (name == "run_every_frame") { state.session.runEveryFrame = a.get<bool>(); return ""; }
  if (name == "print_timing") { printTiming(state, a.get<std::string>()); return ""; }
  if (name == "print_pick") { printPick(state, a.get<std::string>()); return ""; }
  if (name == "camera_moving") { state.script.movesCamera = a.get<bool>(); return ""; }
  if (name == "trace_window") { state.views.traceWindow = a.get<bool>(); return ""; }
  if (name == "mouse") { state.script.cursorRequest = glm::vec2(a[0].get<float>(), a[1].get<float>()); return ""; }
  return runMore(state, action);
}

#include "window/script/ui_script_actions.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "base/input_error.h"
#include "io/headless_session.h"
#include "base/json_input.h"
#include "io/output_path.h"

#include "window/panels/ui_export.h"
#include "window/panels/ui_reference_progress.h"
#include "window/panels/ui_speed_error.h"
#include "window/panels/ui_temporal.h"
#include "window/script/ui_lesson_crop.h"
#include "window/script/ui_lesson_export.h"
#include "window/script/ui_settings.h"
#include "window/ui_camera.h"
#include "window/ui_graph.h"
#include "window/ui_layout_report.h"
#include "window/ui_live_truth.h"
#include "window/ui_log_panel.h"
#include "window/ui_scale.h"
#include "window/ui_state.h"
#include "window/views/ui_view_difference.h"
#include "window/views/ui_view_toolbar.h"

using nlohmann::json;

// The output rule for scripts and lessons (io/output_path.h, README "Scripts and lessons"):
// with an export directory, a path is relative, without "..", and lands under it; a
// lesson's whole directory is one transaction, opened at its first file.
std::string ScriptContext::resolved(const std::string& path) {
  if (std::string problem = checkScriptPath(path, !exportDirectory.empty()); !problem.empty())
    throw InputError("'" + printable(path, 200) + "': " + problem);
  if (exportDirectory.empty()) return path;
  if (!transactional) return (std::filesystem::path(exportDirectory) / path).string();
  if (!transaction) {
    checkOutputDirectory(exportDirectory, "the lesson's export folder", kLessonManifest);
    transaction = std::make_shared<DirectoryTransaction>(exportDirectory, kLessonManifest);
  }
  return (transaction->path() / path).string();
}

std::string ScriptContext::shown(const std::string& text) const {
  if (!transaction) return text;
  std::string result = text;
  const std::string from = transaction->path().string(), to = transaction->target().string();
  for (size_t at = 0; (at = result.find(from, at)) != std::string::npos; at += to.size())
    result.replace(at, from.size(), to);
  return result;
}

namespace {

// 1. Argument shapes: each returns "" or what was expected.
const ScriptCheck kString = [](const json& v) { return v.is_string() ? "" : "expected a string"; };
const ScriptCheck kObject = [](const json& v) { return v.is_object() ? "" : "expected an object"; };
const ScriptCheck kBool = [](const json& v) {
  return v.is_boolean() ? "" : "expected true or false";
};
// Every number is range-checked here, before the window opens: a handler may convert it
// (to int, to float) without overflow.
std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}
bool inRange(const json& v, double lo, double hi) {
  return v.is_number() && std::isfinite(v.get<double>()) && v.get<double>() >= lo && v.get<double>() <= hi;
}
ScriptCheck integer(long long lo, long long hi) {
  return [lo, hi](const json& v) -> std::string {
    // JSON reads a non-negative integer as unsigned (it may exceed long long's range).
    const bool fits =
        v.is_number_unsigned()
            ? hi >= 0 && v.get<unsigned long long>() <= (unsigned long long)hi &&
                  v.get<unsigned long long>() >= (unsigned long long)std::max(lo, 0LL)
        : v.is_number_integer() ? v.get<long long>() >= lo && v.get<long long>() <= hi
                                : false;
    if (fits) return "";
    return "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  };
}
ScriptCheck number(double lo, double hi, bool openLow = false) {
  return [=](const json& v) -> std::string {
    if (inRange(v, lo, hi) && !(openLow && v.get<double>() <= lo)) return "";
    return std::string("expected a number in ") + (openLow ? "(" : "[") + shortNumber(lo) + ", " +
           shortNumber(hi) + "]";
  };
}
ScriptCheck pair(double lo, double hi) {
  return [=](const json& v) -> std::string {
    if (v.is_array() && v.size() == 2 && inRange(v[0], lo, hi) && inRange(v[1], lo, hi)) return "";
    return "expected [a, b], numbers in [" + shortNumber(lo) + ", " + shortNumber(hi) + "]";
  };
}
ScriptCheck pairOr(double lo, double hi, std::initializer_list<const char*> words) {
  std::vector<std::string> allowed(words.begin(), words.end());
  const ScriptCheck numbers = pair(lo, hi);
  return [allowed, numbers](const json& v) -> std::string {
    const std::string problem = numbers(v);
    if (problem.empty()) return "";
    for (const std::string& word : allowed)
      if (v == word) return "";
    std::string text = problem;
    for (const std::string& word : allowed) text += " or \"" + word + "\"";
    return text;
  };
}
const ScriptCheck kZoom = [](const json& v) -> std::string {
  return (inRange(v, 0, 1e6) && v.get<double>() > 0) || v == "fit" || v == "1:1"
             ? ""
             : "expected a zoom factor in (0, 1e6], \"fit\" or \"1:1\"";
};
// A text the terminal and the lesson panel show (bounded by the reader: base/json_input.h).
const ScriptCheck kText = kString;
// A file or folder a script writes: checked again with the export folder when it runs.
const ScriptCheck kOutput = [](const json& v) -> std::string {
  if (!v.is_string()) return "expected a file or folder name";
  return checkScriptPath(v.get<std::string>(), false);
};
const ScriptCheck kExportView = [](const json& v) -> std::string {
  if (std::string problem = checkExportView(v); !problem.empty()) return problem;
  return checkScriptPath(v.is_string() ? v.get<std::string>() : v["file"].get<std::string>(), false);
};
// A screenshot: its crop (ui_lesson_export.cpp) and its file, checked like export_view's.
const ScriptCheck kScreenshot = [](const json& v) -> std::string {
  if (std::string problem = checkScreenshot(v); !problem.empty()) return problem;
  return checkScriptPath(v.is_string() ? v.get<std::string>() : v["file"].get<std::string>(), false);
};
// Coordinates (image or window pixels; may lie outside the image) and angles: within the
// scene limit of +-1e6 (app/scene/scene.h), far beyond any image or useful angle.
constexpr double kMaxScriptCoordinate = 1e6;

// {"drag": {"from": [x, y], "to": [x, y], "button": ..., "keys": ..., "frames": n}}
std::string checkInputObject(const json& v, std::initializer_list<const char*> keys,
                             const char* shape) {
  if (!v.is_object()) return std::string("expected ") + shape;
  for (const auto& [key, unused] : v.items()) {
    bool known = false;
    for (const char* name : keys) known = known || key == name;
    if (!known) return "unknown key '" + printable(key) + "'; expected " + shape;
  }
  if (v.contains("keys") && !v["keys"].is_string()) return "\"keys\": expected a string such as \"alt+shift\"";
  return "";
}
const ScriptCheck checkDrag = [](const json& v) -> std::string {
  const char* shape = "{\"from\": [x, y], \"to\": [x, y], \"button\": ..., \"keys\": ..., \"frames\": n}";
  if (std::string problem = checkInputObject(v, {"from", "to", "button", "keys", "frames"}, shape); !problem.empty())
    return problem;
  for (const char* point : {"from", "to"})
    if (!v.contains(point) || !pair(-kMaxScriptCoordinate, kMaxScriptCoordinate)(v[point]).empty())
      return std::string("\"") + point + "\": " + pair(-kMaxScriptCoordinate, kMaxScriptCoordinate)(json());
  if (v.contains("button") && !v["button"].is_string()) return "\"button\": expected left, right or middle";
  if (v.contains("frames") && !integer(1, 240)(v["frames"]).empty())
    return "\"frames\": " + integer(1, 240)(json());
  return "";
};
const ScriptCheck checkWheel = [](const json& v) -> std::string {
  const char* shape = "{\"at\": [x, y], \"amount\": n, \"keys\": ...}";
  if (std::string problem = checkInputObject(v, {"at", "amount", "keys"}, shape); !problem.empty())
    return problem;
  if (!v.contains("at") || !pair(-kMaxScriptCoordinate, kMaxScriptCoordinate)(v["at"]).empty())
    return "\"at\": " + pair(-kMaxScriptCoordinate, kMaxScriptCoordinate)(json());
  if (!v.contains("amount") || !number(-100, 100)(v["amount"]).empty())
    return "\"amount\": " + number(-100, 100)(json());
  return "";
};

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

ViewPanel& activeView(UiState& state) { return state.views.panels[state.views.activeView]; }
const GlTexture* activeTexture(UiState& state) { return shownTexture(state, activeView(state)); }

// 2. Handlers longer than a line (the others are in the table).
std::string setParameters(UiState& state, const json& a) {
  const std::string truthKey = groundTruthChoiceKey(state.session.pipeline);
  for (const auto& [key, value] : a.items()) {
    const std::string text = value.is_string() ? value.get<std::string>() : value.dump();
    if (std::string problem = state.session.setParameter(key, text); !problem.empty())
      return problem;
    // A ground truth the script names is its choice, as with --set: the live error keeps it
    // even when it equals the current one (before, "error.against": "reference" set before
    // the first run was overridden by the automatic raster4d on a cheap scene, and a
    // lesson's "against the Embree reference" numbers were against raster4d).
    if (key == truthKey) keepUserTruth(state.liveTruth);
  }
  // A choice naming a disabled stage (composite.shadow = raster4d with raster4d off) is
  // warned about: a later action may still enable it, so it is not refused here.
  std::vector<std::string> assignments;
  for (const auto& [key, value] : a.items())
    assignments.push_back(key + "=" + (value.is_string() ? value.get<std::string>() : value.dump()));
  if (std::string problem = disabledSelection(state.session.pipeline, assignments); !problem.empty()) {
    std::fprintf(stderr, "penumbra: warning: %s\n", problem.c_str());
    state.status = "warning: " + problem;
  }
  return "";
}

std::string pick(UiState& state, const json& a) {
  const GlTexture* texture = activeTexture(state);
  if (!texture) return "the active view shows no texture";
  // Image coordinates (row 0 at the top) -> GL texel (row 0 at the bottom).
  state.views.setPick({a[0].get<int>(), texture->height() - 1 - a[1].get<int>()},
                      {texture->width(), texture->height()});
  return "";
}

std::string exportAll(UiState& state, const json& a, ScriptContext& context) {
  const std::string target = context.resolved(a.get<std::string>());
  // Refused before any work when the folder is not an earlier export (never emptied).
  checkOutputDirectory(target, "export_all", "run.json");
  state.status = context.shown(exportAllStages(state, target));
  std::printf("penumbra: %s\n", state.status.c_str());
  return state.status.rfind("wrote ", 0) == 0 ? "" : state.status;
}

std::string eyeSize(UiState& state, const json& a) {
  if (a == "fit")
    state.session.eye.fitView = true;
  else if (a[0].get<int>() < 16 || a[1].get<int>() < 16 || a[0].get<int>() > 8192 ||
           a[1].get<int>() > 8192)
    return "sizes are in [16, 8192]";
  else
    state.session.eye = {false, a[0].get<int>(), a[1].get<int>()};
  return "";
}

std::string colormap(UiState& state, const json& a) {
  const auto names = colormapNames();
  for (size_t m = 0; m < names.size(); ++m)
    if (names[m] == a) {
      activeView(state).settings.colormap = Colormap(m);
      return "";
    }
  return "unknown colormap; valid: gray, perceptual, diverging, categorical";
}

std::string channels(UiState& state, const json& a) {
  const std::string letters = a.get<std::string>();
  if (letters.find_first_not_of("RGBA") != std::string::npos) return "expected letters from RGBA";
  for (int c = 0; c < 4; ++c)
    activeView(state).settings.channels[size_t(c)] = letters.find("RGBA"[c]) != std::string::npos;
  return "";
}

std::string range(UiState& state, const json& a) {
  ViewPanel& view = activeView(state);
  const GlTexture* texture = activeTexture(state);
  if (a == "autofit")
    view.autofitPending = true;
  else if (a == "reset") {
    if (texture) resetView(state, view, *texture);
  } else {
    view.settings.black = a[0].get<float>();
    view.settings.white = a[1].get<float>();
    view.settings.autoRange = false;
  }
  return "";
}

std::string loadSettings(UiState& state, const json& a) {
  bool ok = false;
  state.status = loadSettingsFile(state, a.get<std::string>(), ok);
  return ok ? "" : state.status;
}

std::string saveSettings(UiState& state, const json& a, ScriptContext& context) {
  state.status = context.shown(saveSettingsFile(state, context.resolved(a.get<std::string>())));
  return state.status.rfind("saved", 0) == 0 ? "" : state.status;
}

// 3. The table. `newFrame`: the next action sees the re-run pipeline and the new layout (a
//    change of parameters, scene or size re-runs anyway: the runner waits while it would).
std::vector<ScriptActionSpec> makeTable() {
  using S = UiState;
  using C = ScriptContext;
  const auto text = [](const json& a) { return a.get<std::string>(); };
  // Labels reach the terminal: control characters removed, bounded.
  const auto label = [](const json& a) { return plainText(a.get<std::string>(), 200); };
  std::vector<ScriptActionSpec> table = {
      {"select_stage", kString, [=](S& s, const json& a, C&) { return s.selectStage(text(a)); },
       true},
      {"select_output", kString, [=](S& s, const json& a, C&) { return s.selectOutput(text(a)); },
       true},
      {"set", kObject, [](S& s, const json& a, C&) { return setParameters(s, a); }},
      {"pick", pair(-kMaxScriptCoordinate, kMaxScriptCoordinate),
       [](S& s, const json& a, C&) { return pick(s, a); }},
      {"select_ray", integer(0, 65535),
       [](S& s, const json& a, C&) {
         s.views.selectedRay = a.get<int>();
         return std::string();
       }},
      {"wait", integer(0, 100000),
       [](S&, const json& a, C& c) {
         c.waitFrames = a.get<int>();
         return std::string();
       }},
      {"export_view", kExportView,
       [](S& s, const json& a, C& c) { return exportView(s, a, c); }},
      {"keep", kObject, [](S& s, const json& a, C& c) { return keepNumbers(s, a, c); }},
      {"collect", kObject, [](S& s, const json& a, C& c) { return collectText(s, a, c); }},
      {"for_each_method", checkForEachMethod,
       [](S& s, const json& a, C& c) {
         c.expanded = expandForEachMethod(s.session.pipeline, a);
         return std::string();
       }},
      {"annotate", kBool,
       [](S&, const json& a, C& c) {
         c.annotate = a.get<bool>();
         return std::string();
       }},
      {"crop", checkCrop,
       [](S&, const json& a, C& c) {
         c.crop = cropFromJson(a);
         return std::string();
       }},
      {"export_all", kOutput, [](S& s, const json& a, C& c) { return exportAll(s, a, c); }},
      {"screenshot", kScreenshot,
       [](S& s, const json& a, C& c) { return screenshot(s, a, c); }},
      {"view", integer(0, kMaxViews - 1),
       [](S& s, const json& a, C&) -> std::string {
         if (a.get<int>() >= kMaxViews) return "views are 0 (A), 1 (B), 2 (C) and 3 (D)";
         if (a.get<int>() >= s.views.shownViews())
           s.views.setLayout(a.get<int>() == 1 ? ViewLayout::SideBySide : ViewLayout::Grid);
         s.views.activeView = a.get<int>();
         return "";
       },
       true},
      {"two_views", kBool,
       [](S& s, const json& a, C&) {
         s.views.setLayout(a.get<bool>() ? ViewLayout::SideBySide : ViewLayout::One);
         return std::string();
       },
       true},
      {"layout", kString,
       [=](S& s, const json& a, C&) -> std::string {
         ViewLayout layout;
         if (!layoutFromName(text(a), layout)) return "unknown layout; valid: one, side_by_side, grid";
         s.views.setLayout(layout);
         return "";
       },
       true},
      {"link_views", kBool,
       [](S& s, const json& a, C&) {
         s.views.linked = a.get<bool>();
         if (s.views.linked) s.views.linkFrom(s.views.activeView);
         return std::string();
       }},
      {"lock", kBool,
       [](S& s, const json& a, C&) {
         activeView(s).locked = a.get<bool>();
         return std::string();
       }},
      {"eye_size", pairOr(16, 8192, {"fit"}), [](S& s, const json& a, C&) { return eyeSize(s, a); }},
      {"scene", kString, [=](S& s, const json& a, C&) { return s.loadScene(text(a)); }},
      // The scene's time (scene/animation.h): posed there, every stage run again.
      {"time", number(-1e9, 1e9), [](S& s, const json& a, C&) { return s.session.setTime(a.get<double>()); }},
      {"play", kBool,
       [](S& s, const json& a, C&) {
         s.session.playing = a.get<bool>();
         return std::string();
       }},
      // The temporal-stability tab (window/panels/ui_temporal.h): forget its pairs; move the
      // frame key after every run.
      {"temporal_clear", kBool,
       [](S& s, const json&, C&) {
         clearTemporalPanel(s);
         return std::string();
       }},
      {"temporal_key", kBool,
       [](S& s, const json& a, C&) {
         setTemporalPerFrameKey(s, a.get<bool>());
         return std::string();
       }},
      {"frame_scene", kBool, [](S& s, const json&, C&) { return frameLoadedScene(s); }},
      {"colormap", kString, [](S& s, const json& a, C&) { return colormap(s, a); }},
      {"channels", kString, [](S& s, const json& a, C&) { return channels(s, a); }},
      {"level", integer(0, 31),
       [](S& s, const json& a, C&) {
         activeView(s).settings.layer = a.get<int>();
         return std::string();
       }},
      {"range", pairOr(-1e30, 1e30, {"autofit", "reset"}), [](S& s, const json& a, C&) { return range(s, a); },
       true},  // autofit applies when the view draws: the next action sees it
      {"overlay", kBool,
       [](S& s, const json& a, C&) {
         activeView(s).settings.overlay = a.get<bool>();
         return std::string();
       }},
      {"zoom", kZoom, [](S& s, const json& a, C&) { return zoomActiveView(s, a); }},
      {"camera_orbit", pair(-kMaxScriptCoordinate, kMaxScriptCoordinate),
       [](S& s, const json& a, C&) -> std::string {
         Camera camera = s.session.scene.camera;
         // Degrees reduced first: radians of 1e6 degrees in float would lose the angle.
         orbitCamera(camera, float(glm::radians(std::fmod(a[0].get<double>(), 360.0))),
                     float(glm::radians(std::fmod(a[1].get<double>(), 360.0))));
         if (!finite(camera.position)) return "the orbit gives a non-finite camera; the camera is unchanged";
         s.session.scene.camera = camera;
         return "";
       }},
      {"camera_dolly", number(1e-3, 1e3),
       [](S& s, const json& a, C&) {
         dollyCamera(s.session.scene.camera, a.get<float>());
         return std::string();
       }},
      {"settings", kObject, [](S& s, const json& a, C&) { return applySettingsJson(s, a); }},
      {"load_settings", kString, [](S& s, const json& a, C&) { return loadSettings(s, a); }},
      {"save_settings", kOutput, [](S& s, const json& a, C& c) { return saveSettings(s, a, c); }},
      {"reload_shaders", kBool,
       [](S& s, const json&, C&) {
         s.reloadShaders();
         return std::string();
       }},
      {"help", kBool,
       [](S& s, const json& a, C&) {
         s.showHelp = a.get<bool>();
         return std::string();
       },
       true},
      {"run_every_frame", kBool,
       [](S& s, const json& a, C&) {
         s.session.runEveryFrame = a.get<bool>();
         return std::string();
       }},
      {"print_timing", kString,
       [=](S& s, const json& a, C&) {
         printTiming(s, label(a));
         return std::string();
       }},
      {"print_frames", kString,
       [=](S& s, const json& a, C&) {
         std::printf("frames %s: %d built, %d drawn\n", text(a).c_str(), s.session.uiFramesBuilt,
                     s.session.uiFramesDrawn);
         std::fflush(stdout);
         return std::string();
       }},
      {"print_log", kString,
       [=](S& s, const json& a, C&) {
         printLog(s, text(a));
         return std::string();
       }},
      {"print_layout", kString,
       [=](S& s, const json& a, C&) {
         printLayout(s, label(a));
         return std::string();
       }},
      {"ui_scale", number(0, 1e3, true),
       [](S& s, const json& a, C&) -> std::string {
         if (!validUiScale(a.get<float>()))
           return "expected a UI scale in [" + std::to_string(kMinUiScale) + ", " + std::to_string(kMaxUiScale) + "]";
         s.uiScale = a.get<float>();
         return "";
       },
       true},
      {"speed_error", kBool,
       [](S& s, const json& a, C&) {
         s.showSpeedError = a.get<bool>();
         return std::string();
       },
       true},
      {"speed_error_measure", kString,
       [=](S& s, const json& a, C& c) {
         s.showSpeedError = true;
         c.waitForSpeedError = true;
         return startSpeedErrorRun(s, text(a));
       },
       true},
      {"compare_with_ground_truth", kBool,
       [](S& s, const json& a, C&) {
         if (!a.get<bool>()) return std::string();
         const std::string problem = compareWithReference(s);
         if (problem.empty()) std::printf("penumbra: live error %s\n", liveTruthLine(s.liveTruth, s.session.pipeline).c_str());
         return problem;
       },
       true},
      {"print_counters", kString,
       [=](S& s, const json& a, C&) {
         std::printf("counters %s:\n", label(a).c_str());
         if (s.session.frame)
           for (const auto& [name, value] : s.session.frame->counters)
             std::printf("  %s %.9g\n", name.c_str(), value);
         std::fflush(stdout);
         return std::string();
       }},
      {"print_truth", kString,
       [=](S& s, const json& a, C&) {
         std::printf("truth %s: %s\n", label(a).c_str(), liveTruthLine(s.liveTruth, s.session.pipeline).c_str());
         std::fflush(stdout);
         return std::string();
       }},
      {"print_pick", kString,
       [=](S& s, const json& a, C&) {
         printPick(s, label(a));
         return std::string();
       }},
      {"camera_moving", kBool,
       [](S& s, const json& a, C&) {
         s.script.movesCamera = a.get<bool>();
         return std::string();
       },
       true},
      {"trace_window", kBool,
       [](S& s, const json& a, C&) {
         s.views.traceWindow = a.get<bool>();
         return std::string();
       },
       true},
      {"mouse", pair(-kMaxScriptCoordinate, kMaxScriptCoordinate),
       [](S& s, const json& a, C&) {
         s.script.cursorRequest = glm::vec2(a[0].get<float>(), a[1].get<float>());
         return std::string();
       }},
      {"drag", checkDrag, [](S& s, const json& a, C&) { return queueDrag(s, a); }},
      {"wheel", checkWheel, [](S& s, const json& a, C&) { return queueWheel(s, a); }},
      {"difference", kString,
       [=](S& s, const json& a, C&) { return setViewDifference(s, activeView(s), text(a)); }, true},
      {"thickness", kBool,
       [](S& s, const json& a, C&) {
         return a.get<bool>() ? showThickness(s) : setViewDifference(s, activeView(s), "");
       },
       true},
      {"clip_negative", kBool,
       [](S& s, const json& a, C&) {
         activeView(s).clipNegative = a.get<bool>();
         return std::string();
       }},
      {"show_light", kBool,
       [](S& s, const json& a, C&) {
         s.views.showLight = a.get<bool>();
         return std::string();
       }},
      {"show_ray", kBool, [](S& s, const json& a, C&) { return showRay(s, a); }},
      {"lesson", kText, [](S& s, const json& a, C& c) { return startLesson(s, a, c); }, true},
      {"say", kText, [](S& s, const json& a, C& c) { return say(s, a, c); }, true},
      {"export_dir", checkExportDirName,
       [=](S&, const json& a, C& c) {
         if (c.transaction) return std::string("export_dir must come before the lesson's first file");
         if (!c.exportOverridden)
           c.exportDirectory = (std::filesystem::path(kDefaultExportDirectory) / text(a)).string();
         return std::string();
       }},
  };
  std::sort(table.begin(), table.end(),
            [](const auto& a, const auto& b) { return a.name < b.name; });
  return table;
}

}  // namespace

const std::vector<ScriptActionSpec>& scriptActions() {
  static const std::vector<ScriptActionSpec> table = makeTable();
  return table;
}

const ScriptActionSpec* findScriptAction(const std::string& name) {
  for (const ScriptActionSpec& spec : scriptActions())
    if (spec.name == name) return &spec;
  return nullptr;
}

std::string scriptActionNames() {
  std::string names;
  for (const ScriptActionSpec& spec : scriptActions())
    names += (names.empty() ? "" : ", ") + spec.name;
  return names;
}

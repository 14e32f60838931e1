#include "window/script/ui_script_actions.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "window/panels/ui_export.h"
#include "window/panels/ui_reference_progress.h"
#include "window/panels/ui_speed_error.h"
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

std::string ScriptContext::resolved(const std::string& path) const {
  if (exportDirectory.empty() || std::filesystem::path(path).is_absolute()) return path;
  return (std::filesystem::path(exportDirectory) / path).string();
}

namespace {

// 1. Argument shapes: each returns "" or what was expected.
const ScriptCheck kString = [](const json& v) { return v.is_string() ? "" : "expected a string"; };
const ScriptCheck kObject = [](const json& v) { return v.is_object() ? "" : "expected an object"; };
const ScriptCheck kBool = [](const json& v) {
  return v.is_boolean() ? "" : "expected true or false";
};
const ScriptCheck kCount = [](const json& v) {
  return v.is_number_integer() && v.get<long long>() >= 0 ? "" : "expected an integer >= 0";
};
const ScriptCheck kPair = [](const json& v) {
  return v.is_array() && v.size() == 2 && v[0].is_number() && v[1].is_number() ? ""
                                                                               : "expected [a, b]";
};
ScriptCheck pairOr(std::initializer_list<const char*> words) {
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
const ScriptCheck kZoom = [](const json& v) -> std::string {
  return (v.is_number() && v.get<double>() > 0) || v == "fit" || v == "1:1"
             ? ""
             : "expected a zoom factor > 0, \"fit\" or \"1:1\"";
};
const ScriptCheck kFactor = [](const json& v) -> std::string {
  return v.is_number() && v.get<double>() > 0 ? "" : "expected a factor > 0";
};

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
    if (key == truthKey) keepUserTruth(state);
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
  state.status = exportAllStages(state, target);
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

std::string saveSettings(UiState& state, const json& a) {
  state.status = saveSettingsFile(state, a.get<std::string>());
  return state.status.rfind("saved", 0) == 0 ? "" : state.status;
}

// 3. The table. `newFrame`: the next action sees the re-run pipeline and the new layout (a
//    change of parameters, scene or size re-runs anyway: the runner waits while it would).
std::vector<ScriptActionSpec> makeTable() {
  using S = UiState;
  using C = ScriptContext;
  const auto text = [](const json& a) { return a.get<std::string>(); };
  std::vector<ScriptActionSpec> table = {
      {"select_stage", kString, [=](S& s, const json& a, C&) { return s.selectStage(text(a)); },
       true},
      {"select_output", kString, [=](S& s, const json& a, C&) { return s.selectOutput(text(a)); },
       true},
      {"set", kObject, [](S& s, const json& a, C&) { return setParameters(s, a); }},
      {"pick", kPair, [](S& s, const json& a, C&) { return pick(s, a); }},
      {"select_ray", kCount,
       [](S& s, const json& a, C&) {
         s.views.selectedRay = a.get<int>();
         return std::string();
       }},
      {"wait", kCount,
       [](S&, const json& a, C& c) {
         c.waitFrames = a.get<int>();
         return std::string();
       }},
      {"export_view", checkExportView,
       [](S& s, const json& a, C& c) { return exportView(s, a, c); }},
      {"keep", kObject, [](S& s, const json& a, C& c) { return keepNumbers(s, a, c); }},
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
      {"export_all", kString, [](S& s, const json& a, C& c) { return exportAll(s, a, c); }},
      {"screenshot", checkScreenshot,
       [](S& s, const json& a, C& c) { return screenshot(s, a, c); }},
      {"view", kCount,
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
      {"eye_size", pairOr({"fit"}), [](S& s, const json& a, C&) { return eyeSize(s, a); }},
      {"scene", kString, [=](S& s, const json& a, C&) { return s.loadScene(text(a)); }},
      {"frame_scene", kBool, [](S& s, const json&, C&) { return frameLoadedScene(s); }},
      {"colormap", kString, [](S& s, const json& a, C&) { return colormap(s, a); }},
      {"channels", kString, [](S& s, const json& a, C&) { return channels(s, a); }},
      {"level", kCount,
       [](S& s, const json& a, C&) {
         activeView(s).settings.layer = a.get<int>();
         return std::string();
       }},
      {"range", pairOr({"autofit", "reset"}), [](S& s, const json& a, C&) { return range(s, a); },
       true},  // autofit applies when the view draws: the next action sees it
      {"overlay", kBool,
       [](S& s, const json& a, C&) {
         activeView(s).settings.overlay = a.get<bool>();
         return std::string();
       }},
      {"zoom", kZoom, [](S& s, const json& a, C&) { return zoomActiveView(s, a); }},
      {"camera_orbit", kPair,
       [](S& s, const json& a, C&) {
         orbitCamera(s.session.scene.camera, glm::radians(a[0].get<float>()),
                     glm::radians(a[1].get<float>()));
         return std::string();
       }},
      {"camera_dolly", kFactor,
       [](S& s, const json& a, C&) {
         dollyCamera(s.session.scene.camera, a.get<float>());
         return std::string();
       }},
      {"settings", kObject, [](S& s, const json& a, C&) { return applySettingsJson(s, a); }},
      {"load_settings", kString, [](S& s, const json& a, C&) { return loadSettings(s, a); }},
      {"save_settings", kString, [](S& s, const json& a, C&) { return saveSettings(s, a); }},
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
         printTiming(s, text(a));
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
       [=](S&, const json& a, C&) {
         printLayout(text(a));
         return std::string();
       }},
      {"ui_scale", kFactor,
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
         if (problem.empty()) std::printf("penumbra: live error %s\n", liveTruthLine(s).c_str());
         return problem;
       },
       true},
      {"print_counters", kString,
       [=](S& s, const json& a, C&) {
         std::printf("counters %s:\n", text(a).c_str());
         if (s.session.frame)
           for (const auto& [name, value] : s.session.frame->counters)
             std::printf("  %s %.9g\n", name.c_str(), value);
         std::fflush(stdout);
         return std::string();
       }},
      {"print_truth", kString,
       [=](S& s, const json& a, C&) {
         std::printf("truth %s: %s\n", text(a).c_str(), liveTruthLine(s).c_str());
         std::fflush(stdout);
         return std::string();
       }},
      {"print_pick", kString,
       [=](S& s, const json& a, C&) {
         printPick(s, text(a));
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
      {"mouse", kPair,
       [](S& s, const json& a, C&) {
         s.script.cursorRequest = glm::vec2(a[0].get<float>(), a[1].get<float>());
         return std::string();
       }},
      {"drag", kObject, [](S& s, const json& a, C&) { return queueDrag(s, a); }},
      {"wheel", kObject, [](S& s, const json& a, C&) { return queueWheel(s, a); }},
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
      {"lesson", kString, [](S& s, const json& a, C& c) { return startLesson(s, a, c); }, true},
      {"say", kString, [](S& s, const json& a, C& c) { return say(s, a, c); }, true},
      {"export_dir", checkExportDirName,
       [=](S&, const json& a, C& c) {
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

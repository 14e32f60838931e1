// The window's model, in parts with one job each: the session (scene, pipeline, runs), the
// views (selection, pick), script I/O and the lesson; plus the messages of the status line.
// The actions here touch more than one part. No ImGui here, so every action a click performs
// can also be performed by a script line.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "window/panels/ui_hash_stats.h"
#include "window/panels/ui_inspector.h"
#include "window/panels/ui_temporal.h"
#include "window/script/ui_script_io.h"
#include "window/ui_export_progress.h"
#include "window/ui_live_truth.h"
#include "window/ui_log.h"
#include "window/ui_record.h"
#include "window/ui_session.h"
#include "window/ui_state_speed_error.h"
#include "window/views/ui_view_colorbar.h"
#include "window/views/ui_view_state.h"

struct Param;
using ParamHandValues = std::map<const Param*, double>;  // as ui_widgets.h (no ImGui here)

class UiState {
public:
  Session session;
  ViewState views;
  ScriptIo script;
  LessonState lesson;
  LiveTruth liveTruth;  // the live error's ground truth (ui_live_truth.h)
  // What the panels keep from one UI frame to the next (here, not in function statics, so
  // that each UiState, a test's included, starts from the defaults).
  struct PanelMemory {
    int shownTab = -1;        // the side panel's tab on screen (window_app.cpp); -1: none yet
    bool wasStacked = false;  // the side panel was one column last frame
    std::string scenePath;    // the scene panel's typed path
    std::string settingsPath = "penumbra_settings.json", exportDirectory;  // the tools' paths
    ParamHandValues handValues;  // a parameter's own value while auto is on (ui_widgets.h)
    InspectorMemory inspector;   // the pick table and the picked ray (ui_inspector.h)
    HashStatsPanelState hashStats;  // the hash comparison and dieharder run (ui_hash_stats.h)
    ExportProgressState exportProgress;  // Export all and the script's progress (ui_export_progress.h)
    TemporalPanelState temporal;  // the temporal-stability tab's plot (ui_temporal.h)
    DrawnColorBars colorBars;     // the views' colour bars last drawn (ui_view_colorbar.h)
    RecordingState recording;     // the Record window and its recording (ui_record.h)
  } panelMemory;
  SpeedErrorPanelState speedError;  // the "Speed vs error" panel (ui_state_speed_error.h)

  // Messages.
  std::string status;     // the status line: what happened last
  UiLog log;              // every warning and error of the session (ui_log.h)
  std::vector<std::string> sceneWarnings;  // app/scene/scene_checks.h, shown in the status line
  AreaLight checkedLight;                  // the light sceneWarnings were computed for
  std::string shaderLog;  // last failed hot reload
  bool showHelp = false, showShaderLog = false, showLog = false;
  bool showSpeedError = false;  // the right panel's "Speed vs error" tab instead of the inspector
  float uiScale = 1;            // fonts and sizes (projectors, high-DPI): app/window/ui_scale.h
  float appliedUiScale = 0;     // the scale the fonts were last built at (0: not yet)
  // What this frame's views show that the draw data does not (their textures' contents),
  // mixed in by each view: the window draws a frame only when it differs (ui_frame_change.h).
  std::uint64_t shownContent = 0;

  // Reports: into the log and onto the status line. fail() passes `problem` through (""
  // logs nothing); reportExport() logs an export's result unless it says what it wrote.
  void report(LogLevel level, const std::string& source, const std::string& message);
  const std::string& fail(const std::string& source, const std::string& problem);
  void reportExport(const std::string& result);
  void reportResult(const std::string& source, const std::string& result, bool ok);  // ok: status only
  bool statusIsProblem() const { return !status.empty() && status == lastProblem_; }

  // Actions. Each returns "" or a message naming what is valid (and logs it).
  std::string loadScene(const std::string& source);  // keeps the old scene on failure
  void adoptScene(Scene loaded, const std::string& source);  // and forgets the pick
  std::string selectOutput(const std::string& stageDotOutput);  // into the active view
  std::string selectStage(const std::string& stage);  // and its first output
  bool reloadShaders();  // ShaderProgram::reloadAll; keeps the last good programs on error

  // The outputs the window shows now: both views (and what they subtract), and the trace
  // stage's outputs while the ray trace panel is open on a picked eye pixel. Only their
  // dependencies run.
  std::vector<std::string> requestedOutputs() const;
  RunKey currentKey() const { return session.currentKey(requestedOutputs()); }
  // Whether the next runIfNeeded would run (the key changed, or run every frame).
  bool needsRun() const;
  bool runIfNeeded(glm::ivec2 viewRegion);  // Session::runIfNeeded on what is shown
  // Before a run at a new full-resolution eye size (a view opened under "fit view", the
  // window resized): a pick made in the eye moves to the same place of the new eye.
  void keepPickInEye(glm::ivec2 viewRegion);
  glm::ivec2 fullEye{0, 0};  // the eye size of the last keepPickInEye outside previews
  void checkLight();  // recomputes sceneWarnings when the light moved since the last check

private:
  void setSceneWarnings(std::vector<std::string> warnings);  // logs the new ones
  std::string lastProblem_;  // the status text of the last report
};

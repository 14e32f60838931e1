// The window's model: scene, pipeline, frame, the two views, the pick, and the actions the
// panels and `--script` share (select, set, pick, load scene). No ImGui here, so every
// action a click performs can also be performed by a script line.
#pragma once
#include <array>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/frame.h"
#include "core/pipeline.h"
#include "scene/scene.h"
#include "window/views/texture_view.h"
#include "window/panels/ui_trace_panel.h"
#include "window/views/ui_view_difference.h"
#include "window/views/ui_view_settings.h"
#include "window/views/ui_view_transform.h"

// One texture view of the centre area.
struct ViewPanel {
  std::string output;         // "stage.output" shown
  bool locked = false;        // a locked view ignores selections in the pipeline panel
  ViewSettings settings;
  std::string settingsFor;    // the output `settings` were initialised from
  ViewTransform transform;
  bool fitPending = true;     // fit on the next draw (new output, new size, "Fit")
  bool fitted = false;        // still as fitted (no zoom / pan since): refit on resize
  bool autofitPending = false;
  glm::vec2 regionSize{0, 0};  // the image region drawn last frame (screen pixels)
  glm::vec2 eyeRegion{0, 0};   // the view's area less a fixed toolbar reserve: "fit view" eye
  glm::ivec2 lastTextureSize{0, 0};  // to keep the picture in place when the size changes
  glm::vec2 regionOrigin{0, 0};  // top-left of the image region last frame (window pixels)
  bool frameOverlays = false;  // zoom onto the ray trace's shapes once they are drawn here
  TextureView renderer;
  // Difference view (app/window/views/ui_view_difference.h): shows output - minus when minus is set.
  std::string minus;
  bool clipNegative = false;  // negative differences shown as 0 (thickness: uncovered texels)
  mutable ViewDifference difference;  // a cache of the GPU result
};

// One frame of mouse and modifier input that a script gives as a user would (ui_script.h
// "drag", "wheel"); window_app.cpp applies it over the backend's input before the UI frame.
struct SyntheticInput {
  glm::vec2 mouse{0, 0};  // window pixels
  std::array<bool, 3> buttons{false, false, false};  // left, right, middle
  bool alt = false, shift = false, ctrl = false;
  float wheel = 0;
};

// The lesson being played (app/window/script/ui_lesson.h): what the panel shows.
struct LessonState {
  std::string title, text;  // the lesson's title; the current "say"
  int step = 0, steps = 0;  // "say" k of n
  bool waiting = false;     // interactive: the next step waits for the student
  bool next = false;        // the student asked for the next step
  bool finished = false;    // interactive: every step played; the window stays open
};

// Eye image size: follows the view (one texel per screen pixel) or fixed.
struct EyeSize {
  bool fitView = true;
  int width = 640, height = 480;
};

// Everything a pipeline run depends on. The window runs the pipeline when the key of what
// it would run now differs from the key of its last run; nobody sets a "dirty" flag.
struct RunKey {
  std::uint64_t revision = 0;  // Pipeline::revision(): every parameter's value
  std::uint64_t scene = 0;     // which scene (loads counted), its camera and light
  glm::ivec2 eye{0, 0};
  std::uint32_t frameKey = 0;
  int shaders = 0;                     // shader reloads
  std::vector<std::string> requested;  // the outputs shown (Pipeline::run's `requested`)
  bool operator==(const RunKey&) const = default;
};

class UiState {
public:
  UiState();  // records the declared parameter defaults (for export names)

  // 1. Scene and pipeline. Frame refers to `scene`, which is replaced in place.
  std::string sceneSource = "cube";
  Scene scene;
  Pipeline pipeline;
  std::unique_ptr<GpuScene> gpuScene;
  std::unique_ptr<Frame> frame;
  EyeSize eye;
  Camera initialCamera;     // as the scene file placed them ("Reset camera / light")
  AreaLight initialLight;
  std::string renderer;  // GL renderer string, for run.json
  std::map<std::string, double> parameterDefaults;  // "stage.key" -> declared default

  // 2. Views, selection, pick.
  ViewPanel views[2];
  int activeView = 0;
  bool twoViews = false;
  std::string selectedStage;
  std::string scrollToStage;  // the pipeline panel brings this stage into view (scripts, views)
  std::optional<glm::ivec2> pick;  // GL texel (row 0 at the bottom) in a texture of `pickSpace`
  glm::ivec2 pickSpace{0, 0};
  int selectedRay = 0;
  std::vector<ViewOverlayShape> overlays;  // drawn by views of matching size (ray trace)
  bool showLight = true;  // the light's outline over eye-sized views (app/window/ui_light_gesture.h)

  // 3. Run control and messages.
  std::optional<RunKey> lastRun;  // the key of the last run (none yet)
  int sceneLoads = 0, shaderReloads = 0;
  bool traceShown = false;     // the inspector's ray trace section is open (it needs the trace)
  bool runEveryFrame = false;  // for timing: run even when the key has not changed
  bool previewing = false;     // camera moving: eye at 1/previewDivisor resolution
  int previewDivisor = 1;      // chosen so a preview run takes about kPreviewMs
  double fullResolutionMs = 0;  // the last run at full resolution
  bool scriptMovesCamera = false;  // a script's "camera_moving": as if the mouse dragged
  std::string status;          // the status line: what happened last
  std::string shaderLog;       // last failed hot reload
  bool showHelp = false, showShaderLog = false;
  bool traceWindow = false;    // the ray trace panel in its own window instead of the inspector
  std::string screenshotRequest;  // saved at the end of this frame (script, key)
  std::optional<glm::vec2> cursorRequest;  // script: move the mouse here (window pixels)
  std::deque<SyntheticInput> syntheticInput;  // script: one entry per frame
  LessonState lesson;

  // 4. Timing: per-stage times live in the pipeline (Pipeline::lastTimes); frame intervals.
  std::deque<double> frameSeconds;
  int pipelineRuns = 0;
  glm::ivec2 requestedEye{0, 0};  // "fit view": runs once the layout holds for a frame

  // Actions. Each returns "" or a message naming what is valid.
  std::string loadScene(const std::string& source);  // keeps the old scene on failure
  void adoptScene(Scene loaded, const std::string& source);  // GpuScene and Frame rebuilt
  std::string selectOutput(const std::string& stageDotOutput);  // into the active view
  std::string selectStage(const std::string& stage);  // and its first output
  std::string setParameter(const std::string& stageDotKey, const std::string& value);
  void setPick(glm::ivec2 texel, glm::ivec2 space);
  void movePick(glm::ivec2 delta);
  bool reloadShaders();  // ShaderProgram::reloadAll; keeps the last good programs on error

  // The view a pipeline-panel selection goes to: the active one unless locked.
  ViewPanel* selectionTarget();
  const Output* outputOf(const std::string& stageDotOutput) const;
  std::vector<std::string> outputKeys() const;  // every declared output, in pipeline order

  // The outputs the window shows now: both views (and what they subtract), and the trace
  // stage's outputs while the ray trace panel is open. Only their dependencies run.
  std::vector<std::string> requestedOutputs() const;
  // The eye size of a run: fixed, or `fitSize` (the view's layout) under "fit view"; reduced
  // while previewing.
  glm::ivec2 eyeFor(glm::ivec2 fitSize) const;
  // The key a run would have now (under "fit view", at the last laid-out size).
  RunKey currentKey() const;
  // Whether the next runIfNeeded would run (the key changed, or run every frame).
  bool needsRun() const;
  // Runs the pipeline when the key changed (or runEveryFrame) at the eye size for
  // `viewRegion`, on the requested outputs only. Returns true if it ran.
  bool runIfNeeded(glm::ivec2 viewRegion);
  // Runs every stage (exports of everything); "" or the failure.
  std::string runAll();
  // Called each frame with whether the mouse moves the camera: starts / ends the preview.
  void setCameraMoving(bool moving);
  // The last run: total of the stages that ran; total of their medians, and the fewest runs
  // any of those medians covers (runs with identical parameters, scene and eye size).
  double lastPipelineMs() const;
  double medianPipelineMs() const;
  int medianRuns() const;
  double framesPerSecond() const;
  void recordFrameInterval(double seconds);
};

// The window's session: the scene, the pipeline on it, and when and how it runs (one part of
// UiState, app/window/ui_state.h). Demand-driven: a run computes only the outputs the window
// shows (Pipeline::run's `requested`), and only when what it depends on changed (RunKey).
#pragma once
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/frame.h"
#include "core/pipeline.h"
#include "scene/scene.h"

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
  double time = 0;                     // seconds into the scene's animation
  int shaders = 0;                     // shader reloads
  int calibration = 0;                 // rendererCalibrationGeneration(): `auto` re-decides
  bool playing = false;  // timelinePlaying: `auto` holds while playing, so Pause runs again
  std::vector<std::string> requested;  // the outputs shown (Pipeline::run's `requested`), sorted
  bool operator==(const RunKey&) const = default;
};

struct Session {
  Session();  // records the declared parameter defaults (for export names)

  // 1. Scene and pipeline. Frame refers to `scene`, which is replaced in place.
  std::string sceneSource = "cube";
  Scene scene;
  Pipeline pipeline;
  std::unique_ptr<GpuScene> gpuScene;
  std::unique_ptr<Frame> frame;
  EyeSize eye;
  Camera initialCamera;  // as the scene file placed them ("Reset camera / light")
  AreaLight initialLight;
  std::string renderer;  // GL renderer string, for run.json
  std::map<std::string, double> parameterDefaults;  // "stage.key" -> declared default

  // 2. Run control.
  std::optional<RunKey> lastRun;  // the key of the last run (none yet)
  int sceneLoads = 0, shaderReloads = 0;
  bool runEveryFrame = false;   // for timing: run even when the key has not changed
  bool previewing = false;      // camera moving: eye at 1/previewDivisor resolution
  // The timeline plays live (timelinePlaysLive, ui_timeline.h; set by the main loop each UI
  // frame): runIfNeeded passes it to its run as Frame::timelinePlaying; runAll never does.
  bool timelinePlaying = false;
  int previewDivisor = 1;       // chosen so a preview run takes about kPreviewMs
  double fullResolutionMs = 0;  // the last run at full resolution
  int pipelineRuns = 0;
  glm::ivec2 requestedEye{0, 0};  // "fit view": runs once the layout holds for a frame
  std::deque<double> frameSeconds;  // time to draw each recent UI frame, waits excluded
  std::deque<double> frameEnds;     // when recent frames ended (seconds, steady clock)
  std::string runError;  // why the last run failed, "" after a success: the frame then holds
                         // new, blank and stale outputs, so exports are refused (ui_export.h)
  // A run refused as too long before it started (core/run_control.h): the parameter that
  // lets it run and its estimate in that parameter's unit; the window asks (ui_run_budget.h).
  std::string budgetKey, budgetMessage;
  double budgetEstimate = 0;

  // 3. Scenes and parameters; "" or a message naming what is valid.
  void adoptScene(Scene loaded, const std::string& source);  // GpuScene and Frame rebuilt,
                                                             // the time back to 0
  // Time (scene/animation.h): `scene` is `rest` posed at `time`. setTime poses it again
  // (GpuScene and Frame rebuilt, the frame key kept), the camera and a light the animation
  // does not move staying where the user put them; every stage then runs on the new pose.
  // "" or why the pose is refused (the scene is then unchanged).
  Scene rest;
  double time = 0;
  bool playing = false;  // the main loop advances `time` by speed x the seconds drawn
  double speed = 1;
  bool animated() const { return !rest.animation.empty(); }
  std::string setTime(double seconds);
  std::string setParameter(const std::string& stageDotKey, const std::string& value);
  const Output* outputOf(const std::string& stageDotOutput) const;
  std::vector<std::string> outputKeys() const;  // every declared output, in pipeline order

  // 4. Runs. The eye size of a run: fixed, or `fitSize` (the view's layout) under "fit
  //    view"; reduced while previewing.
  glm::ivec2 eyeFor(glm::ivec2 fitSize) const;
  // The key a run of `requested` would have now (under "fit view", the last laid-out size).
  RunKey currentKey(std::vector<std::string> requested) const;
  // Whether the frame already holds what `key` asks for: the last run's key, or the same
  // with more outputs requested that the last run wrote anyway (a second view of the same
  // output or of one the first depends on runs nothing).
  bool holds(const RunKey& key) const;
  // The eye size the next run would have, or none while "fit view" waits for the layout.
  std::optional<glm::ivec2> nextEye(glm::ivec2 viewRegion) const;
  // Runs `requested` (and what it depends on) when the key changed or runEveryFrame, at the
  // eye size for `viewRegion`. Returns true if it ran; a failure goes to `problem`.
  bool runIfNeeded(glm::ivec2 viewRegion, const std::vector<std::string>& requested,
                   std::string& problem);
  // Runs every stage (exports of everything); "" or the failure.
  std::string runAll();
  // Called each frame with whether the mouse moves the camera: starts / ends the preview.
  void setCameraMoving(bool moving);

  // 5. Timings of the last run: total of the stages that ran; total of their medians, and the
  //    fewest runs any of those medians covers (runs with identical parameters, scene, size).
  double lastPipelineMs() const;
  double medianPipelineMs() const;
  int medianRuns() const;
  // The UI's speed: 1 / the median time to draw a frame (a run, the UI, the swap; not the
  // wait for input), over the last frames: the rate while something happens. An idle window
  // draws only when woken (input, or every 0.1 s): framesDrawnPerSecond counts the frames
  // that ended in the last second.
  double framesPerSecond() const;
  double framesDrawnPerSecond() const;
  int framesMeasured() const { return int(frameSeconds.size()); }
  int uiFramesBuilt = 0, uiFramesDrawn = 0;  // UI frames built / drawn and swapped (window_app.cpp)
  void recordFrame(double drawSeconds, double endSeconds);
};

#include "window/ui_session.h"

#include "gl/renderer_calibration.h"

#include "core/run_control.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bench/bench_measure.h"  // median

namespace {

constexpr size_t kFrameHistory = 30;  // UI frames in the fps readout
constexpr double kPreviewMs = 80;     // target time of a run while the camera moves

// FNV-1a over the bytes of trivially copyable values (floats of the camera and light).
void mix(std::uint64_t& hash, const void* data, size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < bytes; ++i) hash = (hash ^ p[i]) * 1099511628211ull;
}

std::uint64_t sceneFingerprint(const Scene& scene, int loads) {
  std::uint64_t hash = 1469598103934665603ull;
  mix(hash, &loads, sizeof loads);
  const Camera& c = scene.camera;
  for (const glm::vec3* v : {&c.position, &c.target, &c.up}) mix(hash, v, sizeof *v);
  mix(hash, &c.fovYDegrees, sizeof c.fovYDegrees);
  const AreaLight& l = scene.light;
  for (const glm::vec3* v : {&l.center, &l.forward, &l.up}) mix(hash, v, sizeof *v);
  mix(hash, &l.width, sizeof l.width);
  mix(hash, &l.height, sizeof l.height);
  return hash;
}

}  // namespace

Session::Session() {
  for (const std::string& key : pipeline.paramKeys())
    parameterDefaults[key] = pipeline.param(key).value;
}

// 1. Scenes: the Frame is rebuilt around the new one; a new scene is a new run key.
void Session::adoptScene(Scene loaded, const std::string& source) {
  frame.reset();
  gpuScene.reset();
  rest = std::move(loaded);
  time = 0;
  playing = false;
  scene = poseAt(rest, 0);
  sceneSource = source;
  initialCamera = scene.camera;
  initialLight = scene.light;
  gpuScene = std::make_unique<GpuScene>(scene);
  frame = std::make_unique<Frame>(scene, *gpuScene, pipeline);
  frame->eyeWidth = eye.width;
  frame->eyeHeight = eye.height;
  ++sceneLoads;
}

// 2. Parameters go through Param::set, which range-checks and names the valid range; the
//    pipeline's revision changes with the value, so the next frame runs.
std::string Session::setTime(double seconds) {
  if (!std::isfinite(seconds) || std::abs(seconds) > 1e9) return "time must be finite and within +-1e9 s";
  if (!animated()) {
    time = seconds;
    scene.time = seconds;
    return "";
  }
  rest.camera = scene.camera;
  if (rest.animation.light.empty()) rest.light = scene.light;
  Scene posed = poseAt(rest, seconds);
  if (std::string problem = validateScene(posed); !problem.empty())
    return "the scene at time " + std::to_string(seconds) + " s: " + problem;
  const std::uint32_t frameKey = frame ? frame->frameKey : 0;
  const int width = frame ? frame->eyeWidth : eye.width, height = frame ? frame->eyeHeight : eye.height;
  frame.reset();
  gpuScene.reset();
  scene = std::move(posed);
  gpuScene = std::make_unique<GpuScene>(scene);
  frame = std::make_unique<Frame>(scene, *gpuScene, pipeline);
  frame->eyeWidth = width;
  frame->eyeHeight = height;
  frame->frameKey = frameKey;
  time = seconds;
  // The new frame holds no outputs yet: forget the last run's key so that the next frame runs
  // even when the time is the one already shown (a repeat, a recording's first frame).
  lastRun.reset();
  return "";
}

std::string Session::setParameter(const std::string& stageDotKey, const std::string& value) {
  try {
    if (std::string problem = pipeline.param(stageDotKey).set(value); !problem.empty())
      return stageDotKey + ": " + problem;
  } catch (const std::out_of_range& error) {
    return error.what();
  }
  return "";
}

std::vector<std::string> Session::outputKeys() const {
  std::vector<std::string> keys;
  for (const auto& stage : pipeline.stages())
    for (const Output& output : stage->outputs()) keys.push_back(stage->name() + "." + output.name);
  return keys;
}

const Output* Session::outputOf(const std::string& stageDotOutput) const {
  for (const auto& stage : pipeline.stages())
    for (const Output& output : stage->outputs())
      if (stage->name() + "." + output.name == stageDotOutput) return &output;
  return nullptr;
}

// 3. Runs: only when the key differs from the last run's.
glm::ivec2 Session::eyeFor(glm::ivec2 fitSize) const {
  glm::ivec2 size = eye.fitView ? fitSize : glm::ivec2(eye.width, eye.height);
  return previewing ? glm::max(size / previewDivisor, glm::ivec2(32)) : size;
}

RunKey Session::currentKey(std::vector<std::string> requested) const {
  RunKey key;
  key.revision = pipeline.revision();
  key.scene = sceneFingerprint(scene, sceneLoads);
  key.eye = eyeFor(requestedEye);
  if (frame) key.frameKey = frame->frameKey;
  key.time = time;
  key.shaders = shaderReloads;
  key.calibration = rendererCalibrationGeneration();
  key.playing = timelinePlaying;
  std::sort(requested.begin(), requested.end());
  key.requested = std::move(requested);
  return key;
}

bool Session::holds(const RunKey& key) const {
  if (!lastRun || !frame) return false;
  if (*lastRun == key) return true;
  RunKey same = key;
  same.requested = lastRun->requested;
  if (!(same == *lastRun) || !runError.empty()) return false;
  // Only a request that grew: showing less (albedo instead of the composite) runs the smaller
  // graph, so the timings show what the view costs.
  if (!std::includes(key.requested.begin(), key.requested.end(), lastRun->requested.begin(),
                     lastRun->requested.end()))
    return false;
  return std::all_of(key.requested.begin(), key.requested.end(),
                     [&](const std::string& output) { return frame->has(output); });
}

std::optional<glm::ivec2> Session::nextEye(glm::ivec2 viewRegion) const {
  if (!eye.fitView) return eyeFor({eye.width, eye.height});
  const glm::ivec2 size = glm::max(viewRegion, glm::ivec2(64));
  if (viewRegion.x <= 0 || viewRegion.y <= 0 || size != requestedEye) return std::nullopt;
  return eyeFor(size);
}

// A stage that throws is reported, not fatal.
bool Session::runIfNeeded(glm::ivec2 viewRegion, const std::vector<std::string>& requested,
                          std::string& problem) {
  if (!frame) return false;
  if (eye.fitView && (viewRegion.x <= 0 || viewRegion.y <= 0)) return false;  // no layout yet
  glm::ivec2 size =
      eye.fitView ? glm::max(viewRegion, glm::ivec2(64)) : glm::ivec2(eye.width, eye.height);
  if (eye.fitView && size != requestedEye) {  // resizing: wait until the size holds
    requestedEye = size;
    return false;
  }
  size = eyeFor(size);
  frame->eyeWidth = size.x;
  frame->eyeHeight = size.y;
  const RunKey key = currentKey(requested);
  if (!runEveryFrame && holds(key)) return false;
  lastRun = key;  // a failing run is not retried until something changes
  clearRunCancel();  // Esc cancels the run under way, not the next one
  markRunStart();    // the "running" overlay's clock (panels/ui_run_budget.h)
  // Only this run sees the flag: an export or script run through the same frame does not.
  struct PlayingFlag {
    Frame& frame;
    ~PlayingFlag() { frame.timelinePlaying = false; }
  } playingFlag{*frame};
  frame->timelinePlaying = timelinePlaying;
  try {
    pipeline.run(*frame, key.requested);
  } catch (const RunBudgetExceeded& error) {
    runError = error.what();
    budgetKey = error.budgetKey, budgetMessage = error.what(), budgetEstimate = error.estimate;
    problem = "run refused as too long: " + runError;
    return false;
  } catch (const RunCancelled& error) {
    runError = error.what();
    problem = std::string("run ") + error.what() + "; change anything to run again";
    return false;
  } catch (const std::exception& error) {
    runError = error.what();
    problem = "pipeline failed: " + runError + " (exports are refused until a run succeeds)";
    return false;
  }
  runError.clear();
  ++pipelineRuns;
  if (!previewing) fullResolutionMs = lastPipelineMs();
  return true;
}

std::string Session::runAll() {
  if (!frame) return "no frame yet";
  frame->timelinePlaying = false;  // every stage decides as for an export
  try {
    pipeline.run(*frame);
  } catch (const std::exception& error) {
    runError = error.what();
    return std::string("pipeline: ") + error.what();
  }
  runError.clear();
  ++pipelineRuns;
  return "";
}

// A preview only where the full run is slow: 1/d resolution costs about 1/d^2. Back at full
// resolution, the eye size differs from the last run's, so it runs again.
void Session::setCameraMoving(bool moving) {
  if (moving && !previewing)
    previewDivisor = std::clamp(int(std::ceil(std::sqrt(fullResolutionMs / kPreviewMs))), 1, 4);
  previewing = moving;
}

// 4. Timings of the last run (medians over runs with identical settings:
// docs/decisions/021-stage-timings.md).
double Session::lastPipelineMs() const {
  double total = 0;
  for (const StageTime& time : pipeline.lastTimes()) total += time.ran ? time.milliseconds : 0;
  return total;
}

double Session::medianPipelineMs() const {
  double total = 0;
  for (const StageTime& time : pipeline.lastTimes()) total += time.ran ? time.median : 0;
  return total;
}

int Session::medianRuns() const {
  int runs = 0;
  for (const StageTime& time : pipeline.lastTimes())
    if (time.ran) runs = runs == 0 ? time.runs : std::min(runs, time.runs);
  return runs;
}

void Session::recordFrame(double drawSeconds, double endSeconds) {
  frameSeconds.push_back(drawSeconds);
  if (frameSeconds.size() > kFrameHistory) frameSeconds.pop_front();
  frameEnds.push_back(endSeconds);
  while (frameEnds.front() < endSeconds - 1.0) frameEnds.pop_front();
}

double Session::framesPerSecond() const {
  if (frameSeconds.empty()) return 0;
  const double seconds = median({frameSeconds.begin(), frameSeconds.end()});
  return seconds > 0 ? 1.0 / seconds : 0;
}

double Session::framesDrawnPerSecond() const { return double(frameEnds.size()); }

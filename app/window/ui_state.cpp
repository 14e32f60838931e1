#include "window/ui_state.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "scene/scene_builtin.h"
#include "gl/shader_program.h"
#include "window/ui_graph.h"

namespace {

constexpr size_t kFrameHistory = 30;   // UI frames in the fps readout
constexpr double kPreviewMs = 80;      // target time of a run while the camera moves

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const size_t middle = values.size() / 2;
  return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

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

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

UiState::UiState() {
  for (const std::string& key : pipeline.paramKeys())
    parameterDefaults[key] = pipeline.param(key).value;
}

// 1. Scenes: load first, replace only on success; the Frame is rebuilt around the new one.
std::string UiState::loadScene(const std::string& source) {
  std::vector<std::string> warnings;
  Scene loaded;
  try {
    loaded = ::loadScene(source, warnings);
  } catch (const std::exception& error) {
    return error.what();
  }
  adoptScene(std::move(loaded), source);
  for (const std::string& warning : warnings) status += "; warning: " + warning;
  return "";
}

void UiState::adoptScene(Scene loaded, const std::string& source) {
  frame.reset();
  gpuScene.reset();
  scene = std::move(loaded);
  sceneSource = source;
  initialCamera = scene.camera;
  initialLight = scene.light;
  gpuScene = std::make_unique<GpuScene>(scene);
  frame = std::make_unique<Frame>(scene, *gpuScene, pipeline);
  frame->eyeWidth = eye.width;
  frame->eyeHeight = eye.height;
  pick.reset();
  for (ViewPanel& view : views) view.fitPending = true;
  ++sceneLoads;
  status = "scene '" + scene.name + "' (" + std::to_string(scene.triangleCount()) + " triangles)";
}

// 2. Selection: the active view takes it unless locked, then the other one.
ViewPanel* UiState::selectionTarget() {
  if (!views[activeView].locked) return &views[activeView];
  const int other = 1 - activeView;
  if (twoViews && !views[other].locked) return &views[other];
  return nullptr;
}

std::vector<std::string> UiState::outputKeys() const {
  std::vector<std::string> keys;
  for (const auto& stage : pipeline.stages())
    for (const Output& output : stage->outputs()) keys.push_back(stage->name() + "." + output.name);
  return keys;
}

const Output* UiState::outputOf(const std::string& stageDotOutput) const {
  for (const auto& stage : pipeline.stages())
    for (const Output& output : stage->outputs())
      if (stage->name() + "." + output.name == stageDotOutput) return &output;
  return nullptr;
}

std::string UiState::selectOutput(const std::string& stageDotOutput) {
  const Output* declared = outputOf(stageDotOutput);
  if (!declared)
    return "unknown output '" + stageDotOutput + "'; valid: " + joined(outputKeys());
  ViewPanel* target = selectionTarget();
  if (!target) return "both views are locked: unlock one to show " + stageDotOutput;
  target->output = stageDotOutput;
  target->minus.clear();  // a difference belongs to the output it was made for
  target->clipNegative = false;
  if (frame && frame->has(stageDotOutput)) {
    const GlTexture& texture = frame->texture(stageDotOutput);
    target->settings = defaultViewSettings(*declared, texture.channelCount());
    target->settingsFor = stageDotOutput;
    target->autofitPending = texture.isInteger() && target->settings.colormap != Colormap::Categorical;
  }
  target->fitPending = true;
  selectedStage = stageDotOutput.substr(0, stageDotOutput.find('.'));
  scrollToStage = selectedStage;
  return "";
}

std::string UiState::selectStage(const std::string& stageName) {
  try {
    const Stage& stage = pipeline.stage(stageName);
    selectedStage = stageName;
    scrollToStage = stageName;
    if (stage.outputs().empty()) return "";
    return selectOutput(stageName + "." + stage.outputs().front().name);
  } catch (const std::out_of_range& error) {
    return error.what();
  }
}

// 3. Parameters go through Param::set, which range-checks and names the valid range.
std::string UiState::setParameter(const std::string& stageDotKey, const std::string& value) {
  try {
    if (std::string problem = pipeline.param(stageDotKey).set(value); !problem.empty())
      return stageDotKey + ": " + problem;
  } catch (const std::out_of_range& error) {
    return error.what();
  }
  return "";
}

// 4. The pick stays inside the texture it was made in.
void UiState::setPick(glm::ivec2 texel, glm::ivec2 space) {
  if (space.x <= 0 || space.y <= 0) return;
  pick = glm::clamp(texel, glm::ivec2(0), space - 1);
  pickSpace = space;
}

void UiState::movePick(glm::ivec2 delta) {
  if (pick) setPick(*pick + delta, pickSpace);
}

bool UiState::reloadShaders() {
  std::string log;
  const bool ok = ShaderProgram::reloadAll(log);
  ++shaderReloads;
  if (ok) {
    shaderLog.clear();
    showShaderLog = false;
    status = "shaders reloaded";
  } else {
    shaderLog = log;
    showShaderLog = true;
    status = "shader reload failed: the last good programs stay (see Shader log)";
  }
  return ok;
}

// 5. Demand-driven runs: what is shown, and only when what it depends on changed.
std::vector<std::string> UiState::requestedOutputs() const {
  std::vector<std::string> requested;
  auto add = [&](const std::string& key) {
    if (!key.empty() && outputOf(key) && std::find(requested.begin(), requested.end(), key) == requested.end())
      requested.push_back(key);
  };
  for (int v = 0; v < (twoViews ? 2 : 1); ++v) {
    add(views[v].output);
    add(views[v].minus);
  }
  if (traceShown)
    for (const std::string& key : traceOutputs(pipeline)) add(key);
  std::sort(requested.begin(), requested.end());
  return requested;
}

glm::ivec2 UiState::eyeFor(glm::ivec2 fitSize) const {
  glm::ivec2 size = eye.fitView ? fitSize : glm::ivec2(eye.width, eye.height);
  return previewing ? glm::max(size / previewDivisor, glm::ivec2(32)) : size;
}

RunKey UiState::currentKey() const {
  RunKey key;
  key.revision = pipeline.revision();
  key.scene = sceneFingerprint(scene, sceneLoads);
  key.eye = eyeFor(requestedEye);
  if (frame) key.frameKey = frame->frameKey;
  key.shaders = shaderReloads;
  key.requested = requestedOutputs();
  return key;
}

bool UiState::needsRun() const { return runEveryFrame || !lastRun || *lastRun != currentKey(); }

// A stage that throws is reported, not fatal.
bool UiState::runIfNeeded(glm::ivec2 viewRegion) {
  if (!frame) return false;
  if (eye.fitView && (viewRegion.x <= 0 || viewRegion.y <= 0)) return false;  // no layout yet
  glm::ivec2 size = eye.fitView ? glm::max(viewRegion, glm::ivec2(64))
                                : glm::ivec2(eye.width, eye.height);
  if (eye.fitView && size != requestedEye) {  // resizing: wait until the size holds
    requestedEye = size;
    return false;
  }
  size = eyeFor(size);
  frame->eyeWidth = size.x;
  frame->eyeHeight = size.y;
  const RunKey key = currentKey();
  if (!runEveryFrame && lastRun && *lastRun == key) return false;
  lastRun = key;  // a failing run is not retried until something changes
  try {
    pipeline.run(*frame, key.requested);
  } catch (const std::exception& error) {
    status = std::string("pipeline: ") + error.what();
    return false;
  }
  ++pipelineRuns;
  if (!previewing) fullResolutionMs = lastPipelineMs();
  return true;
}

std::string UiState::runAll() {
  if (!frame) return "no frame yet";
  try {
    pipeline.run(*frame);
  } catch (const std::exception& error) {
    return std::string("pipeline: ") + error.what();
  }
  ++pipelineRuns;
  return "";
}

// A preview only where the full run is slow: 1/d resolution costs about 1/d^2. Back at full
// resolution, the eye size differs from the last run's, so it runs again.
void UiState::setCameraMoving(bool moving) {
  if (moving && !previewing)
    previewDivisor = std::clamp(int(std::ceil(std::sqrt(fullResolutionMs / kPreviewMs))), 1, 4);
  previewing = moving;
}

// 6. Timings of the last run (DESIGN.md §7: medians over runs with identical settings).
double UiState::lastPipelineMs() const {
  double total = 0;
  for (const StageTime& time : pipeline.lastTimes()) total += time.ran ? time.milliseconds : 0;
  return total;
}

double UiState::medianPipelineMs() const {
  double total = 0;
  for (const StageTime& time : pipeline.lastTimes()) total += time.ran ? time.median : 0;
  return total;
}

int UiState::medianRuns() const {
  int runs = 0;
  for (const StageTime& time : pipeline.lastTimes())
    if (time.ran) runs = runs == 0 ? time.runs : std::min(runs, time.runs);
  return runs;
}

void UiState::recordFrameInterval(double seconds) {
  frameSeconds.push_back(seconds);
  if (frameSeconds.size() > kFrameHistory) frameSeconds.pop_front();
}

double UiState::framesPerSecond() const {
  const double seconds = median({frameSeconds.begin(), frameSeconds.end()});
  return seconds > 0 ? 1.0 / seconds : 0;
}

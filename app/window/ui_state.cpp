#include "window/ui_state.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "scene/scene_builtin.h"
#include "gl/shader_program.h"

namespace {

constexpr size_t kTimingHistory = 15;  // pipeline runs in the median
constexpr size_t kFrameHistory = 30;   // UI frames in the fps readout
constexpr double kPreviewMs = 80;      // target time of a run while the camera moves

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const size_t middle = values.size() / 2;
  return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
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
  dirty = true;
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
  dirty = true;
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
  dirty = true;
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

// 5. Runs only when something changed; a stage that throws is reported, not fatal.
bool UiState::runIfNeeded(glm::ivec2 viewRegion) {
  if (!frame) return false;
  if (eye.fitView && (viewRegion.x <= 0 || viewRegion.y <= 0)) return false;  // no layout yet
  glm::ivec2 size = eye.fitView ? glm::max(viewRegion, glm::ivec2(64))
                                : glm::ivec2(eye.width, eye.height);
  if (eye.fitView && size != requestedEye) {  // resizing: wait until the size holds
    requestedEye = size;
    return false;
  }
  if (previewing) size = glm::max(size / previewDivisor, glm::ivec2(32));
  if (size.x != frame->eyeWidth || size.y != frame->eyeHeight) {
    frame->eyeWidth = size.x;
    frame->eyeHeight = size.y;
    recentTimes.clear();  // medians compare runs of one size
    dirty = true;
  }
  if (!dirty && !runEveryFrame) return false;
  dirty = false;
  try {
    pipeline.run(*frame);
  } catch (const std::exception& error) {
    status = std::string("pipeline: ") + error.what();
    return false;
  }
  ++pipelineRuns;
  if (!previewing) {
    fullResolutionMs = 0;
    for (const StageTime& time : pipeline.lastTimes()) fullResolutionMs += time.milliseconds;
  }
  recentTimes.push_back(pipeline.lastTimes());
  if (recentTimes.size() > kTimingHistory) recentTimes.pop_front();
  return true;
}

// A preview only where the full run is slow: 1/d resolution costs about 1/d^2.
void UiState::setCameraMoving(bool moving) {
  if (moving && !previewing)
    previewDivisor = std::clamp(int(std::ceil(std::sqrt(fullResolutionMs / kPreviewMs))), 1, 4);
  if (!moving && previewing && previewDivisor > 1) dirty = true;  // full resolution again
  previewing = moving;
}

// 6. Medians over recent runs (DESIGN.md §7: median of N frames).
double UiState::medianStageMs(const std::string& stage) const {
  std::vector<double> values;
  for (const auto& run : recentTimes)
    for (const StageTime& time : run)
      if (time.stage == stage) values.push_back(time.milliseconds);
  return median(values);
}

double UiState::medianPipelineMs() const {
  std::vector<double> totals;
  for (const auto& run : recentTimes) {
    double total = 0;
    for (const StageTime& time : run) total += time.milliseconds;
    totals.push_back(total);
  }
  return median(totals);
}

void UiState::recordFrameInterval(double seconds) {
  frameSeconds.push_back(seconds);
  if (frameSeconds.size() > kFrameHistory) frameSeconds.pop_front();
}

double UiState::framesPerSecond() const {
  const double seconds = median({frameSeconds.begin(), frameSeconds.end()});
  return seconds > 0 ? 1.0 / seconds : 0;
}

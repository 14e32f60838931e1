#include "window/ui_state.h"

#include "scene/scene_checks.h"

#include <algorithm>
#include <stdexcept>

#include "gl/shader_program.h"
#include "scene/scene_builtin.h"
#include "window/ui_graph.h"

namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

// 1. Scenes: load first, replace only on success.
std::string UiState::loadScene(const std::string& source) {
  std::vector<std::string> warnings;
  Scene loaded;
  try {
    loaded = ::loadScene(source, warnings);
  } catch (const std::exception& error) {
    return fail("scene", error.what());
  }
  adoptScene(std::move(loaded), source);
  for (const std::string& warning : warnings) log.warning("scene", warning);  // they name the file
  if (!warnings.empty()) status += "; warning: " + warnings.front() + (warnings.size() > 1 ? " (more in the log)" : "");
  return "";
}

void UiState::adoptScene(Scene loaded, const std::string& source) {
  session.adoptScene(std::move(loaded), source);
  views.pick.reset();
  for (ViewPanel& view : views.panels) view.fitPending = true;
  const Scene& scene = session.scene;
  status = "scene '" + scene.name + "' (" + std::to_string(scene.triangleCount()) + " triangles)";
  sceneWarnings.clear();  // a new scene: its warnings are logged again
  setSceneWarnings(lightWarnings(scene));
  checkedLight = scene.light;
}

void UiState::checkLight() {
  const AreaLight& l = session.scene.light;
  const AreaLight& c = checkedLight;
  if (l.center == c.center && l.forward == c.forward && l.up == c.up && l.width == c.width &&
      l.height == c.height)
    return;
  setSceneWarnings(lightWarnings(session.scene));
  checkedLight = l;
}

// A warning that persists while the light moves is logged once, when it appears.
void UiState::setSceneWarnings(std::vector<std::string> warnings) {
  for (const std::string& warning : warnings)
    if (std::find(sceneWarnings.begin(), sceneWarnings.end(), warning) == sceneWarnings.end())
      log.warning("scene", warning);
  sceneWarnings = std::move(warnings);
}

// 1b. Reports.
void UiState::report(LogLevel level, const std::string& source, const std::string& message) {
  log.add(level, source, message);
  status = message;
  lastProblem_ = message;
}

const std::string& UiState::fail(const std::string& source, const std::string& problem) {
  if (!problem.empty()) report(LogLevel::Error, source, problem);
  return problem;
}

// Exports answer "wrote ..." when they wrote (ui_export.h), else what went wrong.
void UiState::reportExport(const std::string& result) {
  reportResult("export", result, result.rfind("wrote ", 0) == 0);
}

void UiState::reportResult(const std::string& source, const std::string& result, bool ok) {
  if (ok) status = result;
  else fail(source, result);
}

// 2. Selection: into the view that takes it, with the output's declared display.
std::string UiState::selectOutput(const std::string& stageDotOutput) {
  const Output* declared = session.outputOf(stageDotOutput);
  if (!declared)
    return fail("view", "unknown output '" + stageDotOutput + "'; valid: " + joined(session.outputKeys()));
  ViewPanel* target = views.selectionTarget();
  if (!target) return fail("view", "both views are locked: unlock one to show " + stageDotOutput);
  target->output = stageDotOutput;
  target->minus.clear();  // a difference belongs to the output it was made for
  target->clipNegative = false;
  const Frame* frame = session.frame.get();
  if (frame && frame->has(stageDotOutput)) {
    const GlTexture& texture = frame->texture(stageDotOutput);
    target->settings = defaultViewSettings(*declared, texture.channelCount());
    target->settingsFor = stageDotOutput;
    target->autofitPending =
        texture.isInteger() && target->settings.colormap != Colormap::Categorical;
  }
  target->fitPending = true;
  views.selectedStage = stageDotOutput.substr(0, stageDotOutput.find('.'));
  views.scrollToStage = views.selectedStage;
  return "";
}

std::string UiState::selectStage(const std::string& stageName) {
  try {
    const Stage& stage = session.pipeline.stage(stageName);
    views.selectedStage = stageName;
    views.scrollToStage = stageName;
    if (stage.outputs().empty()) return "";
    return selectOutput(stageName + "." + stage.outputs().front().name);
  } catch (const std::out_of_range& error) {
    return fail("view", error.what());
  }
}

// 3. Shaders: a reload is part of the run key, so the next frame runs with them.
bool UiState::reloadShaders() {
  std::string compileLog;
  const bool ok = ShaderProgram::reloadAll(compileLog);
  ++session.shaderReloads;
  if (ok) {
    shaderLog.clear();
    showShaderLog = false;
    status = "shaders reloaded";
  } else {
    shaderLog = compileLog;
    showShaderLog = true;
    log.error("shaders", "reload failed, the last good programs stay:\n" + compileLog);
    status = "shader reload failed: the last good programs stay (see Shader log)";
    lastProblem_ = status;
  }
  return ok;
}

// 4. Demand-driven runs: what is shown, and only when what it depends on changed.
std::vector<std::string> UiState::requestedOutputs() const {
  std::vector<std::string> requested;
  auto add = [&](const std::string& key) {
    if (!key.empty() && session.outputOf(key) &&
        std::find(requested.begin(), requested.end(), key) == requested.end())
      requested.push_back(key);
  };
  for (int v = 0; v < views.shownViews(); ++v) {
    add(views.panels[v].output);
    add(views.panels[v].minus);
  }
  // The trace panel shows the rays of a picked eye pixel: only then does it need the trace.
  const Frame* frame = session.frame.get();
  const bool eyePick =
      views.pick && frame && views.pickSpace == glm::ivec2(frame->eyeWidth, frame->eyeHeight);
  if (views.traceShown && eyePick)
    for (const std::string& key : traceOutputs(session.pipeline)) add(key);
  return requested;
}

bool UiState::needsRun() const {
  return session.runEveryFrame || !session.holds(currentKey());
}

void UiState::keepPickInEye(glm::ivec2 viewRegion) {
  const std::optional<glm::ivec2> eye = session.nextEye(viewRegion);
  if (!eye || session.previewing) return;
  if (fullEye != glm::ivec2(0)) views.followResize(fullEye, *eye);
  fullEye = *eye;
}

bool UiState::runIfNeeded(glm::ivec2 viewRegion) {
  checkLight();
  updateLiveTruth(liveTruth, session, requestedOutputs(), status);
  std::string problem;
  const bool ran = session.runIfNeeded(viewRegion, requestedOutputs(), problem);
  fail("pipeline", problem);
  if (ran) recordLiveTruthRun(liveTruth, session);
  return ran;
}

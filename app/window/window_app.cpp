#include "window/window_app.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "gl/gl_context.h"
#include "core/input_error.h"
#include "io/image_export.h"
#include "io/output_path.h"
#include "scene/scene_builtin.h"
#include "window/panels/ui_export.h"
#include "window/ui_help.h"
#include "window/ui_scale.h"
#include "window/panels/ui_inspector.h"
#include "window/script/ui_lesson.h"
#include "window/panels/ui_pipeline_panel.h"
#include "window/panels/ui_scene_panel.h"
#include "window/script/ui_script.h"
#include "window/watchdog.h"
#include "io/json_input.h"
#include "window/script/ui_settings.h"
#include "window/panels/ui_speed_error.h"
#include "window/ui_graph.h"
#include "window/ui_state.h"
#include "window/views/ui_texture_view.h"
#include "window/views/ui_ssm_pick.h"
#include "window/views/ui_trace_source.h"
#include "window/views/ui_view_toolbar.h"

namespace {

constexpr ImGuiWindowFlags kPanelFlags =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
    ImGuiWindowFlags_NoBringToFrontOnFocus;

// 1. Fixed layout: panels scale with the window, within limits.
struct Layout {
  float width, height, left, right, status;
  float centerWidth() const { return width - left - right; }
  float panelHeight() const { return height - status; }
};

Layout layoutFor(float width, float height, float uiScale) {
  return {width, height, std::clamp(width * 0.27f, 220.0f * uiScale, 360.0f * uiScale),
          std::clamp(width * 0.23f, 220.0f * uiScale, 330.0f * uiScale), ImGui::GetFrameHeight() + 6};
}

void saveScreenshot(GLFWwindow* window, const std::string& path) {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window, &width, &height);
  std::vector<std::uint8_t> rgb(size_t(width) * height * 3), flipped(rgb.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  const size_t row = size_t(width) * 3;
  for (int y = 0; y < height; ++y)
    std::copy_n(&rgb[size_t(height - 1 - y) * row], row, &flipped[size_t(y) * row]);
  // A lesson's or script's export folder may not exist yet (its first file is a screenshot).
  if (const std::filesystem::path parent = std::filesystem::path(path).parent_path(); !parent.empty())
    std::filesystem::create_directories(parent);
  writePng(path, flipped, width, height);
}

// 2. Keyboard shortcuts (listed by ui_help.cpp); none while a text field has the keyboard.
void handleShortcuts(UiState& state, GLFWwindow* window, int& screenshotCount) {
  ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  bool question = false;
  for (ImWchar c : io.InputQueueCharacters) question |= c == '?';
  if (ImGui::IsKeyPressed(GLFW_KEY_F1) || question) state.showHelp = !state.showHelp;
  if (ImGui::IsKeyPressed(GLFW_KEY_F5)) state.reloadShaders();
  if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE)) glfwSetWindowShouldClose(window, GLFW_TRUE);
  if (ImGui::IsKeyPressed(GLFW_KEY_F12))
    state.script.screenshotRequest = "penumbra_screenshot_" + std::to_string(++screenshotCount) + ".png";
  if (io.KeyCtrl) {
    if (ImGui::IsKeyPressed(GLFW_KEY_S, false))
      state.status = saveSettingsFile(state, "penumbra_settings.json");
    if (ImGui::IsKeyPressed(GLFW_KEY_E, false)) state.status = exportAllStages(state, "");
    return;
  }
  ViewState& views = state.views;
  if (ImGui::IsKeyPressed(GLFW_KEY_TAB, false)) views.activeView = (views.activeView + 1) % views.shownViews();
  if (ImGui::IsKeyPressed(GLFW_KEY_V, false))
    views.setLayout(views.layout == ViewLayout::SideBySide ? ViewLayout::One : ViewLayout::SideBySide);
  if (ImGui::IsKeyPressed(GLFW_KEY_G, false))
    views.setLayout(views.layout == ViewLayout::Grid ? ViewLayout::One : ViewLayout::Grid);
  if (ImGui::IsKeyPressed(GLFW_KEY_L, false)) {
    views.linked = !views.linked;
    if (views.linked) views.linkFrom(views.activeView);
  }
  ViewPanel& view = state.views.panels[state.views.activeView];
  const GlTexture* texture = shownTexture(state, view);
  if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) view.fitPending = true;
  if (ImGui::IsKeyPressed(GLFW_KEY_1, false)) {
    view.transform.oneToOne();
    view.fitted = false;
  }
  if (ImGui::IsKeyPressed(GLFW_KEY_A, false) && texture) autofitView(view, *texture);
  if (ImGui::IsKeyPressed(GLFW_KEY_R, false) && texture) resetView(state, view, *texture);
  const int step = io.KeyShift ? 10 : 1;
  if (ImGui::IsKeyPressed(GLFW_KEY_LEFT)) state.views.movePick({-step, 0});
  if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT)) state.views.movePick({step, 0});
  if (ImGui::IsKeyPressed(GLFW_KEY_UP)) state.views.movePick({0, step});  // GL: y grows upwards
  if (ImGui::IsKeyPressed(GLFW_KEY_DOWN)) state.views.movePick({0, -step});
}

// 3. The status line: what happened last, and how fast things are.
void drawStatusLine(const UiState& state, const Layout& layout) {
  ImGui::SetNextWindowPos({0, layout.panelHeight()});
  ImGui::SetNextWindowSize({layout.width, layout.status});
  ImGui::Begin("##status", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar |
                                        ImGuiWindowFlags_NoScrollbar);
  char speed[200];
  const double pipelineMs = state.session.medianPipelineMs();
  std::snprintf(speed, sizeof speed, "eye %dx%d | pipeline %.1f ms (%.1f/s, median of %d) | UI %.0f fps | %s%s",
                state.session.frame ? state.session.frame->eyeWidth : 0, state.session.frame ? state.session.frame->eyeHeight : 0,
                pipelineMs, pipelineMs > 0 ? 1000.0 / pipelineMs : 0.0, state.session.medianRuns(),
                state.session.framesPerSecond(),
                state.session.runEveryFrame ? "runs every frame" : "runs on change",
                state.session.previewing && state.session.previewDivisor > 1
                    ? (" | PREVIEW at 1/" + std::to_string(state.session.previewDivisor) +
                       " resolution while the camera moves").c_str()
                    : "");
  float speedWidth = ImGui::CalcTextSize(speed).x;
  if (speedWidth > 0.55f * layout.width) {  // large UI scale: the numbers only
    std::snprintf(speed, sizeof speed, "eye %dx%d | %.1f ms | UI %.0f fps%s",
                  state.session.frame ? state.session.frame->eyeWidth : 0,
                  state.session.frame ? state.session.frame->eyeHeight : 0, pipelineMs,
                  state.session.framesPerSecond(), state.session.previewing ? " | PREVIEW" : "");
    speedWidth = ImGui::CalcTextSize(speed).x;
  }
  const float padding = ImGui::GetStyle().WindowPadding.x;
  ImGui::PushClipRect(ImGui::GetCursorScreenPos(),
                      {layout.width - speedWidth - 2 * padding, layout.height}, true);
  if (!state.sceneWarnings.empty()) {  // what the depth-map methods cannot show (scene_checks.h)
    ImGui::TextColored({1.0f, 0.8f, 0.2f, 1.0f}, "warning: %s%s", state.sceneWarnings.front().c_str(),
                       state.sceneWarnings.size() > 1 ? " (+ more: hover)" : "");
    if (ImGui::IsItemHovered()) {
      std::string all;
      for (const std::string& warning : state.sceneWarnings) all += warning + "\n";
      ImGui::SetTooltip("%s", all.c_str());
    }
    ImGui::SameLine();
  }
  ImGui::TextUnformatted(state.status.empty() ? "F1: help" : state.status.c_str());
  ImGui::PopClipRect();
  ImGui::SameLine(layout.width - speedWidth - padding);
  ImGui::TextUnformatted(speed);
  ImGui::End();
}

// 3b. The right panel: the inspector, or the speed-vs-error chart, as tabs. A script's
//     request (state.showSpeedError) selects a tab; a click on a tab sets the request.
void drawSidePanel(UiState& state, const Layout& layout) {
  ImGui::SetNextWindowPos({layout.width - layout.right, 0});
  ImGui::SetNextWindowSize({layout.right, layout.panelHeight()});
  ImGui::Begin("##side", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar);
  static int shownTab = 0;
  const int wanted = state.showSpeedError ? 1 : 0;
  const bool pending = wanted != shownTab;
  if (ImGui::BeginTabBar("##side_tabs")) {
    const char* names[2] = {"Inspector", "Speed vs error"};
    for (int tab = 0; tab < 2; ++tab) {
      const ImGuiTabItemFlags flags = pending && wanted == tab ? ImGuiTabItemFlags_SetSelected : 0;
      if (!ImGui::BeginTabItem(names[tab], nullptr, flags)) continue;
      shownTab = tab;
      ImGui::BeginChild("##side_tab");  // scrolls under the tab bar, which stays in place
      if (tab == 0) {
        drawInspector(state);
      } else {
        state.views.overlays.clear();  // the ray's shapes are the inspector's
        drawSpeedErrorPanel(state);
      }
      ImGui::EndChild();
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
  }
  if (!pending) state.showSpeedError = shownTab == 1;
  ImGui::End();
}

// 4. One UI frame: left, centre, right, status line, floating windows.
bool drawUi(UiState& state, const Layout& layout) {
  ImGui::SetNextWindowPos({0, 0});
  ImGui::SetNextWindowSize({layout.left, layout.panelHeight()});
  ImGui::Begin("Pipeline (thesis Algorithm 1)", nullptr, kPanelFlags);
  drawScenePanel(state);
  drawPipelinePanel(state);
  ImGui::End();

  ImGui::SetNextWindowPos({layout.left, 0});
  ImGui::SetNextWindowSize({layout.centerWidth(), layout.panelHeight()});
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {4, 4});
  ImGui::Begin("##views", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar |
                                       ImGuiWindowFlags_NoScrollbar);
  ImGui::PopStyleVar();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  bool movingCamera = false;
  const ImVec2 spacing = ImGui::GetStyle().ItemSpacing;
  const int columns = state.views.layout == ViewLayout::One ? 1 : 2;
  const int rows = state.views.layout == ViewLayout::Grid ? 2 : 1;
  const ImVec2 cell{(avail.x - spacing.x * float(columns - 1)) / float(columns),
                    (avail.y - spacing.y * float(rows - 1)) / float(rows)};
  for (int v = 0; v < state.views.shownViews(); ++v) {
    if (v % columns != 0) ImGui::SameLine();
    movingCamera |= drawTextureView(state, v, cell);
  }
  ImGui::End();

  drawSidePanel(state, layout);

  drawStatusLine(state, layout);
  drawLessonWindow(state, layout.left + 0.5f * layout.centerWidth(), layout.centerWidth() - 24,
                   layout.panelHeight());
  stepSpeedErrorPanel();
  drawHelpWindow(state);
  drawShaderLogWindow(state);
  return movingCamera;
}

// A script's drag or wheel: this frame's mouse and modifiers, over what the backend read.
void applySyntheticInput(UiState& state) {
  if (state.script.syntheticInput.empty()) return;
  const SyntheticInput input = state.script.syntheticInput.front();
  state.script.syntheticInput.pop_front();
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = {input.mouse.x, input.mouse.y};
  for (int b = 0; b < 3; ++b) io.MouseDown[b] = input.buttons[size_t(b)];
  io.KeyAlt = input.alt;
  io.KeyShift = input.shift;
  io.KeyCtrl = input.ctrl;
  io.MouseWheel = input.wheel;
}

// 5. What can be checked before a window opens: output paths, scene, --set, script.
int checkOptions(const WindowOptions& options, Scene& scene, std::vector<ScriptAction>& script) {
  try {
    if (!options.screenshot.empty()) checkOutputFile(options.screenshot, "--screenshot");
    if (!options.exportDirectory.empty()) checkOutputDirectory(options.exportDirectory, "--export", "");
  } catch (const InputError& error) {
    std::fprintf(stderr, "penumbra: %s\n", error.what());
    return 2;
  }
  std::vector<std::string> warnings;
  try {
    scene = loadScene(options.scene, warnings);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "penumbra: %s\n", error.what());
    return 2;
  }
  Pipeline check;
  for (const std::string& assignment : options.sets)
    if (std::string problem = check.set(assignment); !problem.empty()) {
      std::fprintf(stderr, "penumbra: --set %s\n", problem.c_str());
      return 2;
    }
  // The readers' rule (io/json_input.h): a FIFO or device is refused here, never waited on.
  if (!options.config.empty()) try {
      readJsonFile(options.config);
    } catch (const InputError& error) {
      std::fprintf(stderr, "penumbra: --config %s\n", error.what());
      return 2;
    }
  if (!options.script.empty()) {
    const char* label = options.lessonCommand ? "penumbra lesson: " : "penumbra: --script ";
    std::string problem = parseScriptFile(options.script, script);
    if (problem.empty())
      problem = checkScriptOutputs(script, {options.interactiveLesson, options.exportDirectory, options.script});
    if (!problem.empty()) {
      std::fprintf(stderr, "%s%s\n", label, problem.c_str());
      return 2;
    }
  }
  return 0;
}

// 6. State after the context exists: scene, --config, then --set, then the final image.
int prepareState(UiState& state, const WindowOptions& options, Scene scene) {
  state.adoptScene(std::move(scene), options.scene);
  if (!options.config.empty()) {
    bool ok = false;
    const std::string message = loadSettingsFile(state, options.config, ok);
    if (!ok) {
      std::fprintf(stderr, "penumbra: --config %s\n", message.c_str());
      return 2;
    }
    state.status = message;
  }
  for (const std::string& assignment : options.sets) state.session.pipeline.set(assignment);
  // A ground truth chosen by --set or --config is the user's: the live error keeps it.
  const std::string truthKey = groundTruthChoiceKey(state.session.pipeline);
  if (!truthKey.empty()) {
    const Param& truth = state.session.pipeline.param(truthKey);
    bool chosen = truth.value != state.session.parameterDefaults[truthKey];
    for (const std::string& assignment : options.sets)
      chosen |= assignment.rfind(truthKey + "=", 0) == 0;
    if (chosen) keepUserTruth(state);
  }
  if (!state.views.panels[0].output.empty()) return 0;  // the views of --config
  if (const std::string image = finalImageOutput(state.session.pipeline); !image.empty()) state.selectOutput(image);
  else state.selectStage(state.session.pipeline.stages().back()->name());
  state.views.scrollToStage.clear();  // open on the top of the pipeline panel
  return 0;
}

}  // namespace

// 7. Setup, the frame loop, teardown.
int runWindow(const WindowOptions& options) {
  Scene scene;
  std::vector<ScriptAction> actions;
  if (int status = checkOptions(options, scene, actions)) return status;
  // Unattended runs end with a message rather than hang (tests, lesson exports).
  std::unique_ptr<Watchdog> watchdog;
  if (!options.interactiveLesson && (!options.script.empty() || !options.screenshot.empty()))
    watchdog = std::make_unique<Watchdog>(options.lessonCommand ? "lesson " + options.script : options.script.empty() ? "--screenshot " + options.screenshot : "--script " + options.script, 300);
  std::string error;
  std::unique_ptr<GlContext> context = GlContext::createWindow(options.width, options.height, "penumbra", error);
  if (!context) {
    std::fprintf(stderr, "penumbra: %s\nWithout a display, run: penumbra export --scene %s --out out\n",
                 error.c_str(), options.scene.c_str());
    return 1;
  }
  GLFWwindow* window = context->window();
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 450 core");

  int result = 0;
  try {
    auto state = std::make_unique<UiState>();  // GL objects: destroyed before the context
    state->session.renderer = context->renderer();
    installFrameTraceSource();
    result = prepareState(*state, options, std::move(scene));
    std::unique_ptr<ScriptRunner> runner;
    if (!options.script.empty())
      runner = std::make_unique<ScriptRunner>(
          std::move(actions), ScriptOptions{options.interactiveLesson, options.exportDirectory, options.script});
    int framesRendered = 0, screenshotCount = 0;
    bool draggingSlider = false;
    auto last = std::chrono::steady_clock::now();
    while (result == 0 && !glfwWindowShouldClose(window)) {
      // 7a. Events: wait when idle, so an idle window costs no CPU.
      const bool busy = (runner && !state->lesson.waiting) || !options.screenshot.empty() ||
                        state->needsRun() || !state->script.syntheticInput.empty();
      if (busy) glfwPollEvents();
      else glfwWaitEventsTimeout(0.1);
      const auto now = std::chrono::steady_clock::now();
      state->session.recordFrameInterval(std::chrono::duration<double>(now - last).count());
      last = now;
      // 7b. Script actions, once the first run and the layout have settled.
      if (runner && framesRendered >= 2 && state->session.pipelineRuns > 0) {
        const ScriptRunner::Step step = runner->step(*state);
        if (step == ScriptRunner::Step::Failed) {
          std::fprintf(stderr, "%s%s\n", options.lessonCommand ? "penumbra lesson: " : "penumbra: ",
                       runner->error().c_str());
          result = 2;
          break;
        }
        if (step == ScriptRunner::Step::Done) {
          if (!options.interactiveLesson) break;
          runner.reset();  // a student's lesson ends; the window stays theirs
          state->lesson.finished = true;
        }
      }
      if (state->script.cursorRequest) {  // a script's "mouse": as if the user moved it there
        glfwSetCursorPos(window, state->script.cursorRequest->x, state->script.cursorRequest->y);
        state->script.cursorRequest.reset();
      }
      // 7c. The pipeline, only when something changed.
      int width = 0, height = 0;
      glfwGetFramebufferSize(window, &width, &height);
      state->keepPickInEye(glm::ivec2(state->views.panels[0].eyeRegion));
      recordPickedPixel(*state);
      pickSoftShadowMapTexels(*state);
      state->runIfNeeded(glm::ivec2(state->views.panels[0].eyeRegion));
      // 7d. The UI (fonts rebuilt first when the UI scale changed).
      applyUiScale(state->uiScale);
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      applySyntheticInput(*state);
      ImGui::NewFrame();
      handleShortcuts(*state, window, screenshotCount);
      const RunKey before = state->currentKey();
      const bool moving = drawUi(*state, layoutFor(ImGui::GetIO().DisplaySize.x, ImGui::GetIO().DisplaySize.y, state->uiScale));
      // A slider dragged since its press counts as moving too: preview until released.
      if (!ImGui::IsAnyItemActive()) draggingSlider = false;
      else if (state->currentKey() != before) draggingSlider = true;
      state->session.setCameraMoving(moving || draggingSlider || state->script.movesCamera);
      ImGui::Render();
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glViewport(0, 0, width, height);
      glClearColor(0.1f, 0.1f, 0.1f, 1);
      glClear(GL_COLOR_BUFFER_BIT);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      ++framesRendered;
      // 7e. Screenshots: requested (script, F12), or --screenshot after --frames.
      if (!state->script.screenshotRequest.empty()) {
        saveScreenshot(window, state->script.screenshotRequest);
        std::printf("penumbra: wrote %s\n", state->script.screenshotRequest.c_str());
        state->status = "screenshot " + state->script.screenshotRequest;
        state->script.screenshotRequest.clear();
      }
      // (An interactive lesson waits for the student: its screenshot shows where it waits.)
      if ((!runner || options.interactiveLesson) && !options.screenshot.empty() &&
          framesRendered >= options.frames) {
        saveScreenshot(window, options.screenshot);
        std::printf("penumbra: wrote %s after %d frames\n", options.screenshot.c_str(), framesRendered);
        break;
      }
      glfwSwapBuffers(window);
    }
  } catch (const std::exception& failure) {
    std::fprintf(stderr, "penumbra: %s\n", failure.what());
    result = 1;
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return result;
}

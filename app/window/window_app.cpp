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
#include "base/input_error.h"
#include "io/renderer_calibration_measure.h"
#include "io/headless_session.h"
#include "io/image_export.h"
#include "io/output_path.h"
#include "scene/scene_builtin.h"
#include "window/ui_frame_change.h"
#include "window/ui_frame_recover.h"
#include "window/ui_help.h"
#include "window/ui_log_panel.h"
#include "window/ui_scale.h"
#include "window/panels/ui_inspector.h"
#include "window/script/ui_lesson.h"
#include "window/panels/ui_pipeline_panel.h"
#include "window/panels/ui_run_budget.h"
#include "window/panels/ui_scene_panel.h"
#include "window/script/ui_script.h"
#include "window/watchdog.h"
#include "base/json_input.h"
#include "window/script/ui_settings.h"
#include "window/panels/ui_speed_error.h"
#include "window/panels/ui_temporal.h"
#include "window/ui_graph.h"
#include "window/ui_state.h"
#include "window/ui_status_line.h"
#include "window/ui_layout.h"
#include "window/ui_timeline.h"
#include "window/ui_record.h"
#include "window/ui_export_progress.h"
#include "window/views/ui_texture_view.h"
#include "window/views/ui_ssm_pick.h"
#include "window/views/ui_trace_source.h"
#include "window/views/ui_view_toolbar.h"

namespace {

constexpr ImGuiWindowFlags kPanelFlags =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
    ImGuiWindowFlags_NoBringToFrontOnFocus;

// 1. Fixed layout: window/ui_layout.h (panels, views, the timeline and lesson strips).

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
//    Nothing but the window manager's close button and Ctrl+Q closes the window (Esc does not).
void handleShortcuts(UiState& state, GLFWwindow* window, int& screenshotCount) {
  ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  bool question = false;
  for (ImWchar c : io.InputQueueCharacters) question |= c == '?';
  if (ImGui::IsKeyPressed(GLFW_KEY_F1) || question) state.showHelp = !state.showHelp;
  if (ImGui::IsKeyPressed(GLFW_KEY_F5)) state.reloadShaders();
  // Esc cancels a run under way (panels/ui_run_budget.h); it does not close the window.
  if (ImGui::IsKeyPressed(GLFW_KEY_F12))
    state.script.screenshotRequest = "penumbra_screenshot_" + std::to_string(++screenshotCount) + ".png";
  if (io.KeyCtrl) {
    if (ImGui::IsKeyPressed(GLFW_KEY_Q, false)) glfwSetWindowShouldClose(window, GLFW_TRUE);
    if (ImGui::IsKeyPressed(GLFW_KEY_S, false)) {
      const std::string result = saveSettingsFile(state, "penumbra_settings.json");
      state.reportResult("settings", result, result.rfind("saved ", 0) == 0);
    }
    if (ImGui::IsKeyPressed(GLFW_KEY_E, false)) requestExportAll(state, "");  // ui_export_progress.h
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

// 3. The status line: window/ui_status_line.h.

// 3b. The side tabs: the inspector and the speed-vs-error chart in the right panel, or, in a
//     window too narrow for two side panels (Layout::stacked), the pipeline too, all in
//     one column on the left. A script's request (state.showSpeedError) selects the chart; a
//     click on a tab sets the request.
void drawSidePanel(UiState& state, const Layout& layout) {
  enum Tab { kPipeline, kInspector, kChart, kTemporal };
  if (layout.stacked) ImGui::SetNextWindowPos({0, 0});
  else ImGui::SetNextWindowPos({layout.width - layout.right, 0});
  ImGui::SetNextWindowSize({layout.stacked ? layout.left : layout.right, layout.panelHeight()});
  ImGui::Begin("##side", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar);
  int& shownTab = state.panelMemory.shownTab;
  int wanted = shownTab;
  if (state.showSpeedError) wanted = kChart;
  else if (wanted == kChart) wanted = kInspector;  // the chart's request withdrawn: the inspector again
  else if (wanted < 0) wanted = layout.stacked ? kPipeline : kInspector;
  if (!layout.stacked && wanted == kPipeline) wanted = kInspector;  // the pipeline has its own panel
  bool& wasStacked = state.panelMemory.wasStacked;  // collapsing (a larger UI scale): the pipeline stays in sight
  if (layout.stacked && !wasStacked && wanted == kInspector) wanted = kPipeline;
  wasStacked = layout.stacked;
  const bool pending = wanted != shownTab;
  if (ImGui::BeginTabBar("##side_tabs")) {
    // One column holds three tabs: the chart's goes by a shorter name (its tooltip has the long one).
    const char* names[4] = {"Pipeline", "Inspector", layout.stacked ? "Chart###chart" : "Speed vs error###chart",
                            "Temporal"};
    for (int tab = layout.stacked ? kPipeline : kInspector; tab <= kTemporal; ++tab) {
      const ImGuiTabItemFlags flags = pending && wanted == tab ? ImGuiTabItemFlags_SetSelected : 0;
      const bool open = ImGui::BeginTabItem(names[tab], nullptr, flags);
      if (tab == kChart && layout.stacked && ImGui::IsItemHovered()) ImGui::SetTooltip("Speed vs error");
      if (!open) continue;
      shownTab = tab;
      ImGui::BeginChild("##side_tab");  // scrolls under the tab bar, which stays in place
      if (tab == kPipeline) {
        drawScenePanel(state);
        drawPipelinePanel(state);
      } else if (tab == kInspector) {
        drawInspector(state);
      } else if (tab == kChart) {
        state.views.overlays.clear();  // the ray's shapes are the inspector's
        drawSpeedErrorPanel(state);
      } else {
        state.views.overlays.clear();
        drawTemporalPanel(state);
      }
      ImGui::EndChild();
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
  }
  if (!pending) state.showSpeedError = shownTab == kChart;
  ImGui::End();
}

// 4. One UI frame: left, centre, right, status line, lesson, floating windows.
bool drawUi(UiState& state, const Layout& layout) {
  if (!layout.stacked) {
    ImGui::SetNextWindowPos({0, 0});
    ImGui::SetNextWindowSize({layout.left, layout.panelHeight()});
    ImGui::Begin("Pipeline (thesis Algorithm 1)", nullptr, kPanelFlags);
    drawScenePanel(state);
    drawPipelinePanel(state);
    ImGui::End();
  }

  ImGui::SetNextWindowPos({layout.left, 0});
  ImGui::SetNextWindowSize({layout.centerWidth(), layout.viewsHeight()});
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
  if (layout.timeline > 0)
    if (std::string problem = drawTimeline(state, state.uiScale, layout.left, layout.viewsHeight(),
                                           layout.centerWidth(), layout.timeline);
        !problem.empty())
      state.status = problem;
  if (layout.lesson > 0)
    drawLessonWindow(state, layout.left, layout.viewsHeight() + layout.timeline, layout.centerWidth(),
                     layout.lesson);
  stepSpeedErrorPanel(state);
  stepTemporalPanel(state);  // after this frame's run, whether its tab is shown or not
  drawHelpWindow(state);
  drawShaderLogWindow(state);
  drawLogWindow(state);
  drawRunBudgetModal(state);
  drawRecordWindow(state);  // ui_record.h
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
int checkOptions(const WindowOptions& options, Scene& scene, std::vector<std::string>& warnings,
                 std::vector<ScriptAction>& script) {
  try {
    if (!options.screenshot.empty()) checkOutputFile(options.screenshot, "--screenshot");
    if (!options.exportDirectory.empty()) checkOutputDirectory(options.exportDirectory, "--export", "");
  } catch (const InputError& error) {
    std::fprintf(stderr, "penumbra: %s\n", error.what());
    return 2;
  }
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
  // The readers' rule (base/json_input.h): a FIFO or device is refused here, never waited on.
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

// 6. State after the context exists: scene (its loader's warnings into the log), --config,
//    then --set, then the final image.
int prepareState(UiState& state, const WindowOptions& options, Scene scene,
                 const std::vector<std::string>& warnings) {
  state.adoptScene(std::move(scene), options.scene);
  for (const std::string& warning : warnings) state.log.warning("scene", warning);  // they name the file
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
  // A --set choice naming a disabled stage (composite.shadow=raster4d, raster4d off) would
  // silently use nothing. The command line refuses it (decision 083); the window warns in
  // its log and status line, since the stage can be enabled in the pipeline panel.
  if (std::string problem = disabledSelection(state.session.pipeline, options.sets); !problem.empty())
    state.report(LogLevel::Warning, "--set", problem);  // the log echoes it to stderr
  // A ground truth chosen by --set or --config is the user's: the live error keeps it.
  const std::string truthKey = groundTruthChoiceKey(state.session.pipeline);
  if (!truthKey.empty()) {
    const Param& truth = state.session.pipeline.param(truthKey);
    bool chosen = truth.value != state.session.parameterDefaults[truthKey];
    for (const std::string& assignment : options.sets)
      chosen |= assignment.rfind(truthKey + "=", 0) == 0;
    if (chosen) keepUserTruth(state.liveTruth);
  }
  if (!state.views.panels[0].output.empty()) return 0;  // the views of --config
  if (const std::string image = finalImageOutput(state.session.pipeline); !image.empty()) state.selectOutput(image);
  else state.selectStage(state.session.pipeline.stages().back()->name());
  state.views.scrollToStage.clear();  // open on the top of the pipeline panel
  return 0;
}

// 7. One frame: events, script, run, UI, screenshots. Returns false when the window is done
//    (a script ended or failed, --screenshot written); `result` then holds the exit status.
struct FrameLoop {
  FrameLoop(const WindowOptions& o, GLFWwindow* w, UiState& s, std::unique_ptr<ScriptRunner>& r)
      : options(o), window(w), state(s), runner(r) {}
  const WindowOptions& options;
  GLFWwindow* window;
  UiState& state;
  std::unique_ptr<ScriptRunner>& runner;
  int framesRendered = 0, screenshotCount = 0;  // UI frames built (drawn or not)
  bool draggingSlider = false;
  int result = 0;
  FrameChange change;
  TimelineClock timeline;

  bool frame() {
    // 7a. Events: wait when idle, so an idle window costs no CPU.
    const bool busy = (runner && !state.lesson.waiting) || !options.screenshot.empty() ||
                      state.needsRun() || !state.script.syntheticInput.empty() ||
                      state.session.playing || recordingActive(state);
    if (busy) glfwPollEvents();
    else glfwWaitEventsTimeout(0.1);
    // The inspector's "measure again": between frames, outside any run (its own pipeline).
    if (takeRecalibrationRequest() && applyRendererCalibration("window", "refresh") != 0)
      state.log.error("calibration", "measuring failed: the previous calibration stays");
    const auto woken = std::chrono::steady_clock::now();
    // 7b. Script actions, once the first run and the layout have settled.
    if (runner && framesRendered >= 2 && state.session.pipelineRuns > 0) {
      const ScriptRunner::Step step = runner->step(state);
      if (step == ScriptRunner::Step::Failed) {
        state.log.echo = false;  // said once, below, as scripts always have
        state.log.error("script", runner->error());
        std::fprintf(stderr, "%s%s\n", options.lessonCommand ? "penumbra lesson: " : "penumbra: ",
                     runner->error().c_str());
        result = 2;
        return false;
      }
      if (step == ScriptRunner::Step::Done) {
        if (!options.interactiveLesson) return false;
        runner.reset();  // a student's lesson ends; the window stays theirs
        state.lesson.finished = true;
      }
    }
    exportsBetweenFrames(state, runner.get(), !options.interactiveLesson);  // their progress shows
    if (state.script.cursorRequest) {  // a script's "mouse": as if the user moved it there
      glfwSetCursorPos(window, state.script.cursorRequest->x, state.script.cursorRequest->y);
      state.script.cursorRequest.reset();
    }
    // 7c. The pipeline, only when something changed.
    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    state.keepPickInEye(glm::ivec2(state.views.panels[0].eyeRegion));
    recordPickedPixel(state);
    pickStageMapTexels(state);
    // The timeline: a playing animation poses the scene at its new time (ui_timeline.h); a
    // recording poses each frame's time around the run (ui_record.h).
    if (std::string problem = advanceTimeline(
            state.session, timeline,
            std::chrono::duration<double>(woken.time_since_epoch()).count());
        !problem.empty())
      state.status = problem;
    const bool ran = runRecordingFrame(state, glm::ivec2(state.views.panels[0].eyeRegion));
    // 7d. The UI (fonts rebuilt first when the UI scale changed).
    applyUiScale(state.uiScale, state.appliedUiScale);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    applySyntheticInput(state);
    ImGui::NewFrame();
    const bool input = userInput();
    handleShortcuts(state, window, screenshotCount);
    const RunKey before = state.currentKey();
    state.shownContent = 0;
    const bool moving = drawUi(state, layoutFor(ImGui::GetIO().DisplaySize.x, ImGui::GetIO().DisplaySize.y, state.uiScale,
                                                 lessonPanelHeight(state), timelineHeight(state.session)));
    // A slider dragged since its press counts as moving too: preview until released.
    if (!ImGui::IsAnyItemActive()) draggingSlider = false;
    else if (state.currentKey() != before) draggingSlider = true;
    // A playing timeline moves the scene every frame: it previews like a drag (the full
    // size runs again on Pause). Not under a script, whose exports are of full-size frames.
    const bool playing = timelinePlaysLive(state.session, runner != nullptr);
    state.session.timelinePlaying = playing;  // `auto` holds its choices (light.auto_while_playing)
    state.session.setCameraMoving(moving || draggingSlider || state.script.movesCamera || playing);
    ImGui::Render();
    ++framesRendered;
    ++state.session.uiFramesBuilt;
    // 7e. Drawn and swapped only when it shows something new (ui_frame_change.h), or a
    //     screenshot reads it: requested (script, F12), or --screenshot after --frames.
    // (An interactive lesson waits for the student: its screenshot shows where it waits.)
    const bool finalShot = (!runner || options.interactiveLesson) && !options.screenshot.empty() &&
                           framesRendered >= options.frames;
    // Exposed (uncovered, restored: RunCancelKeys's refresh callback), or the overlay covered it.
    const bool exposed = takeWindowExposed(window);
    if (exposed || takeRunOverlayDrawn(window)) change.forceNext();
    const bool draw = change.changed(*ImGui::GetDrawData(), state.shownContent);
    if (!draw && !finalShot && state.script.screenshotRequest.empty()) return true;
    present(width, height);
    ++state.session.uiFramesDrawn;
    if (!state.script.screenshotRequest.empty()) {
      const std::string path = state.script.screenshotRequest;
      state.script.screenshotRequest.clear();  // once, even if it cannot be written
      saveScreenshot(window, path);
      std::printf("penumbra: wrote %s\n", path.c_str());
      state.status = "screenshot " + path;
    }
    if (finalShot) {
      saveScreenshot(window, options.screenshot);
      std::printf("penumbra: wrote %s after %d frames\n", options.screenshot.c_str(), framesRendered);
      return false;
    }
    glfwSwapBuffers(window);
    // The UI's speed: frames drawn because something happened (input, a run, a script), not
    // those that only showed the new speed (they would feed themselves).
    const auto done = std::chrono::steady_clock::now();
    if (input || ran || runner)
      state.session.recordFrame(std::chrono::duration<double>(done - woken).count(),
                                std::chrono::duration<double>(done.time_since_epoch()).count());
    return true;
  }

  void present(int width, int height) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glClearColor(0.1f, 0.1f, 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  }

  // Whether the user did anything this frame (after ImGui::NewFrame).
  static bool userInput() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.MouseDelta.x != 0 || io.MouseDelta.y != 0 || io.MouseWheel != 0 || io.MouseWheelH != 0 ||
        !io.InputQueueCharacters.empty())
      return true;
    for (bool down : io.MouseDown)
      if (down) return true;
    for (bool down : io.KeysDown)
      if (down) return true;
    return false;
  }

  // 7f. The one rule: an exception in a frame (a stage, a panel, an action) goes to the log
  //     and the status line; the session, its settings and the window stay. The frame it
  //     left midway is closed as ImGui expects and shown as far as it was drawn. Unattended
  //     runs (a script played through, --screenshot) end instead, with status 1: their
  //     figures would be wrong.
  bool recover(const std::string& what) {
    state.report(LogLevel::Error, "window", what);
    state.script.screenshotRequest.clear();
    if (closeInterruptedFrame()) {
      int width = 0, height = 0;
      glfwGetFramebufferSize(window, &width, &height);
      present(width, height);
      glfwSwapBuffers(window);
      change.forceNext();
    }
    const bool unattended = (runner && !options.interactiveLesson) || !options.screenshot.empty();
    if (unattended) result = 1;
    return !unattended;
  }
};

}  // namespace

// 8. Setup, the frame loop, teardown.
int runWindow(const WindowOptions& options) {
  Scene scene;
  std::vector<std::string> warnings;
  std::vector<ScriptAction> actions;
  if (int status = checkOptions(options, scene, warnings, actions)) return status;
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
  // `auto` per renderer (gl/renderer_calibration.h), before the first run.
  if (int status = applyRendererCalibration("window"); status != 0) return status;
  GLFWwindow* window = context->window();
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 450 core");
  auto cancelKeys = std::make_unique<RunCancelKeys>(window);  // Esc cancels a run in progress

  int result = 0;
  try {
    auto state = std::make_unique<UiState>();  // GL objects: destroyed before the context
    state->log.echo = true;  // the terminal shows what the log shows
    state->session.renderer = context->renderer();
    installFrameTraceSource(state->views);
    result = prepareState(*state, options, std::move(scene), warnings);
    std::unique_ptr<ScriptRunner> runner;
    if (!options.script.empty())
      runner = std::make_unique<ScriptRunner>(
          std::move(actions), ScriptOptions{options.interactiveLesson, options.exportDirectory, options.script});
    FrameLoop loop{options, window, *state, runner};
    while (result == 0 && !glfwWindowShouldClose(window)) {
      try {
        if (!loop.frame()) break;
      } catch (const std::exception& failure) {
        if (!loop.recover(failure.what())) break;
      }
    }
    if (result == 0) result = loop.result;
  } catch (const std::exception& failure) {
    std::fprintf(stderr, "penumbra: %s\n", failure.what());
    result = 1;
  }
  ImGui_ImplOpenGL3_Shutdown();
  cancelKeys.reset();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return result;
}

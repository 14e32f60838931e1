#include "window/panels/ui_run_budget.h"

#include <epoxy/gl.h>

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <imgui_internal.h>  // GImGui->WithinFrameScope

#include <cmath>
#include <cstdio>
#include <vector>

#include "core/progress.h"
#include "core/run_control.h"
#include "window/ui_state.h"
#include "window/ui_widgets.h"

void drawRunBudgetModal(UiState& state) {
  Session& session = state.session;
  const char* title = "This run would take long";
  if (!session.budgetKey.empty() && !ImGui::IsPopupOpen(title)) ImGui::OpenPopup(title);
  ImGui::SetNextWindowSize({uiPixels(520), 0});
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::TextWrapped("%s", session.budgetMessage.c_str());
  ImGui::Spacing();
  ImGui::TextWrapped("Run anyway raises %s to %.0f for this run (a longer one asks again); "
                     "Esc stops a run under way.",
                     session.budgetKey.c_str(), std::ceil(session.budgetEstimate * 1.25));
  if (ImGui::Button("Run anyway")) {
    char value[32];
    std::snprintf(value, sizeof value, "%.0f", std::ceil(session.budgetEstimate * 1.25));
    if (std::string problem = session.setParameter(session.budgetKey, value); !problem.empty())
      state.status = problem;
    session.budgetKey.clear();
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) {
    state.status = "long run cancelled; lower the setting or press Run anyway to run it";
    session.budgetKey.clear();
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

namespace {

// The "running" overlay (header). The UI frame on screen when the run began, kept as copies
// of its draw lists (ImGui rebuilds the originals in the next frame), is drawn again with a
// small window over it holding the Cancel button: a real ImGui frame, so the
// button is clicked as any other, between two checks of the run.
constexpr double kOverlayAfterSeconds = 1.0;  // shorter runs never show it
constexpr double kOverlayInterval = 0.1;      // seconds between two overlay frames

}  // namespace

struct RunCancelKeys::Overlay {
  unsigned run = ~0u;           // runSerial() of the run it was captured for
  std::vector<ImDrawList*> lists;  // copies of the frame on screen when the run began
  ImVec2 displayPos{0, 0}, displaySize{0, 0}, framebufferScale{1, 1};
  double lastDrawn = -1;
  bool announced = false;
  bool drawnSinceTaken = false;
};

namespace {

using Overlay = RunCancelKeys::Overlay;

void releaseCapture(Overlay& overlay) {
  for (ImDrawList* list : overlay.lists) IM_DELETE(list);
  overlay.lists.clear();
}

// A view's texture still alive and still 2D (a name a stage freed may come back as another
// kind of texture, which ImGui's GL_TEXTURE_2D bind would refuse).
bool live2D(ImTextureID id) {
  const GLuint name = GLuint(reinterpret_cast<intptr_t>(id));
  if (!glIsTexture(name)) return false;
  GLint target = 0;
  glGetTextureParameteriv(name, GL_TEXTURE_TARGET, &target);
  return target == GL_TEXTURE_2D;
}

// Drops the commands whose texture is gone: ImGui's renderer binds a command's texture even
// when it draws no element, so a dropped command draws nothing with the font atlas bound.
// Checked again before every overlay frame, since the run may free a view's texture (a stage
// reallocating its output) after the capture.
void dropDeadTextures(std::vector<ImDrawList*>& lists) {
  const ImTextureID font = ImGui::GetIO().Fonts->TexID;
  for (ImDrawList* list : lists)
    for (ImDrawCmd& command : list->CmdBuffer)
      if (command.UserCallback || (command.TextureId != font && !live2D(command.TextureId))) {
        command.ElemCount = 0;
        command.UserCallback = nullptr;
        command.TextureId = font;
      }
}

// The last frame ImGui rendered (what the screen shows), copied.
void captureLastFrame(Overlay& overlay) {
  releaseCapture(overlay);
  const ImDrawData* data = ImGui::GetDrawData();
  if (!data || !data->Valid) return;
  for (int i = 0; i < data->CmdListsCount; ++i)
    overlay.lists.push_back(data->CmdLists[i]->CloneOutput());
  overlay.displayPos = data->DisplayPos;
  overlay.displaySize = data->DisplaySize;
  overlay.framebufferScale = data->FramebufferScale;
}

void renderCapture(Overlay& overlay) {
  if (overlay.lists.empty()) return;
  dropDeadTextures(overlay.lists);
  ImDrawData data;
  data.Valid = true;
  data.CmdLists = overlay.lists.data();
  data.CmdListsCount = int(overlay.lists.size());
  for (ImDrawList* list : overlay.lists) {
    data.TotalVtxCount += list->VtxBuffer.Size;
    data.TotalIdxCount += list->IdxBuffer.Size;
  }
  data.DisplayPos = overlay.displayPos;
  data.DisplaySize = overlay.displaySize;
  data.FramebufferScale = overlay.framebufferScale;
  ImGui_ImplOpenGL3_RenderDrawData(&data);
}

// One overlay frame, from the poll hook, in the middle of a run: the GL state the stage has
// set is kept (ImGui's renderer restores what it changes; the framebuffers, colour mask,
// clear colour and scissor test are restored here).
void drawRunningOverlay(GLFWwindow* window, Overlay& overlay) {
  ImGuiContext* context = ImGui::GetCurrentContext();
  if (!context || context->WithinFrameScope) return;  // a run started from inside a UI frame
  const double elapsed = secondsSinceRunStart();
  if (elapsed < kOverlayAfterSeconds) return;
  if (overlay.run != runSerial()) {
    overlay.run = runSerial();
    captureLastFrame(overlay);
    overlay.lastDrawn = -1;
    overlay.announced = false;
  }
  if (overlay.lastDrawn >= 0 && elapsed - overlay.lastDrawn < kOverlayInterval) return;
  overlay.lastDrawn = elapsed;
  const std::string where = runProgress();
  if (!overlay.announced) {  // the terminal hears it too (and tests wait for it)
    std::fprintf(stderr, "penumbra: a run is taking long (%s); Cancel or Esc stops it\n",
                 where.empty() ? "under way" : where.c_str());
    overlay.announced = true;
  }

  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  // Centred on the window, the button in the middle (tests click the window's centre).
  ImGui::SetNextWindowPos({0.5f * display.x, 0.5f * display.y}, ImGuiCond_Always, {0.5f, 0.5f});
  ImGui::Begin("##run_overlay", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove);
  ImGui::Text("Running the pipeline: %.1f s", elapsed);
  ImGui::TextDisabled("%s", where.empty() ? "under way" : where.c_str());
  if (const ProgressState progress = currentProgress(); progress.active && progress.total > 0)  // an export
    ImGui::ProgressBar(float(progress.fraction()), {ImGui::CalcTextSize("tiles or reference tiles. Settings and the last image stay.").x, 0},
                       (std::to_string(progress.done) + " / " + std::to_string(progress.total) + " " + progress.detail).c_str());
  const ImVec2 button{ImGui::GetContentRegionAvail().x, 2 * ImGui::GetFrameHeight()};
  if (runCancelRequested()) {
    ImGui::Button("cancelling...", button);
  } else if (ImGui::ButtonEx("Cancel run", button, ImGuiButtonFlags_PressedOnClick)) {
    // On the press, not the release: the next overlay frame may be a whole tile away.
    requestRunCancel("Cancel clicked");
  }
  ImGui::TextDisabled("(or press Esc) The run stops at its next check: between stages, SSM\n"
                      "tiles or reference tiles. Settings and the last image stay.");
  ImGui::End();
  ImGui::Render();

  GLint drawFramebuffer = 0, readFramebuffer = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer);
  GLboolean mask[4];
  glGetBooleani_v(GL_COLOR_WRITEMASK, 0, mask);
  GLfloat clear[4];
  glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
  const GLboolean scissor = glIsEnabled(GL_SCISSOR_TEST);
  int width = 0, height = 0;
  glfwGetFramebufferSize(window, &width, &height);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_SCISSOR_TEST);
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  renderCapture(overlay);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  glfwSwapBuffers(window);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFramebuffer));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFramebuffer));
  glColorMaski(0, mask[0], mask[1], mask[2], mask[3]);
  glClearColor(clear[0], clear[1], clear[2], clear[3]);
  if (scissor) glEnable(GL_SCISSOR_TEST);
  overlay.drawnSinceTaken = true;
}

// Esc seen by a key callback (chained before ImGui's): a press and its release can both
// arrive within one poll during a long tile, where glfwGetKey would read "released".
void keyCallback(GLFWwindow* window, int key, int scancode, int action, int mods) {
  if (auto* keys = static_cast<RunCancelKeys*>(glfwGetWindowUserPointer(window)))
    keys->onKey(window, key, scancode, action, mods);
}

void refreshCallback(GLFWwindow* window) {
  if (auto* keys = static_cast<RunCancelKeys*>(glfwGetWindowUserPointer(window))) keys->onRefresh();
}

}  // namespace

RunCancelKeys::RunCancelKeys(GLFWwindow* window)
    : window_(window), overlay_(std::make_unique<Overlay>()) {
  glfwSetWindowUserPointer(window, this);
  previousKeyCallback_ = glfwSetKeyCallback(window, keyCallback);
  glfwSetWindowRefreshCallback(window, refreshCallback);
  setRunCancelPoll([this] {
    escapePressed_ = false;
    glfwPollEvents();
    if (escapePressed_ || glfwGetKey(window_, GLFW_KEY_ESCAPE) == GLFW_PRESS)
      requestRunCancel("Esc pressed");
    else if (glfwWindowShouldClose(window_))
      requestRunCancel("the window is closing");
    drawRunningOverlay(window_, *overlay_);
  });
}

RunCancelKeys::~RunCancelKeys() {
  setRunCancelPoll(nullptr);
  releaseCapture(*overlay_);
  glfwSetKeyCallback(window_, previousKeyCallback_);
  glfwSetWindowRefreshCallback(window_, nullptr);
  glfwSetWindowUserPointer(window_, nullptr);
}

void RunCancelKeys::onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
  if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS) escapePressed_ = true;
  if (previousKeyCallback_) previousKeyCallback_(window, key, scancode, action, mods);
}

bool RunCancelKeys::takeOverlayDrawn() {
  const bool drawn = overlay_->drawnSinceTaken;
  overlay_->drawnSinceTaken = false;
  return drawn;
}

bool RunCancelKeys::takeExposed() {
  const bool exposed = exposed_;
  exposed_ = false;
  return exposed;
}

bool takeWindowExposed(GLFWwindow* window) {
  auto* keys = static_cast<RunCancelKeys*>(glfwGetWindowUserPointer(window));
  return keys && keys->takeExposed();
}

bool takeRunOverlayDrawn(GLFWwindow* window) {
  auto* keys = static_cast<RunCancelKeys*>(glfwGetWindowUserPointer(window));
  return keys && keys->takeOverlayDrawn();
}

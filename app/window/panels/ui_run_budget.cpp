#include "window/panels/ui_run_budget.h"

#include <epoxy/gl.h>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cmath>
#include <cstdio>

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

// Esc seen by a key callback (chained before ImGui's): a press and its release can both
// arrive within one poll during a long tile, where glfwGetKey would read "released".
GLFWkeyfun previousKeyCallback = nullptr;
bool escapePressed = false;

void keyCallback(GLFWwindow* window, int key, int scancode, int action, int mods) {
  if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS) escapePressed = true;
  if (previousKeyCallback) previousKeyCallback(window, key, scancode, action, mods);
}

}  // namespace

void installRunCancelKeys(GLFWwindow* window) {
  static GLFWwindow* installed = nullptr;
  if (!window) {
    setRunCancelPoll(nullptr);
    if (installed) glfwSetKeyCallback(installed, previousKeyCallback);
    installed = nullptr;
    return;
  }
  installed = window;
  previousKeyCallback = glfwSetKeyCallback(window, keyCallback);
  setRunCancelPoll([window] {
    escapePressed = false;
    glfwPollEvents();
    if (escapePressed || glfwGetKey(window, GLFW_KEY_ESCAPE) == GLFW_PRESS)
      requestRunCancel("Esc pressed");
    else if (glfwWindowShouldClose(window))
      requestRunCancel("the window is closing");
  });
}

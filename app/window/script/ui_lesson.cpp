#include "window/script/ui_lesson.h"

#include <imgui.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "window/ui_state.h"

void drawLessonWindow(UiState& state, float centreX, float width, float bottom) {
  LessonState& lesson = state.lesson;
  if (lesson.text.empty() && lesson.title.empty()) return;
  ImGui::SetNextWindowPos({centreX, bottom - 8}, ImGuiCond_Always, {0.5f, 1.0f});
  ImGui::SetNextWindowSize({width, 0}, ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.88f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;
  const std::string title = "Lesson: " + (lesson.title.empty() ? std::string("(untitled)") : lesson.title) +
                            "###lesson";
  if (ImGui::Begin(title.c_str(), nullptr, flags)) {
    if (lesson.steps > 0) ImGui::TextColored({0.95f, 0.8f, 0.4f, 1}, "Step %d of %d", lesson.step, lesson.steps);
    ImGui::PushTextWrapPos(0);
    ImGui::TextUnformatted(lesson.text.c_str());
    ImGui::PopTextWrapPos();
    if (lesson.waiting) {
      const bool key = !ImGui::GetIO().WantTextInput &&
                       (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false) || ImGui::IsKeyPressed(GLFW_KEY_N, false));
      if (ImGui::Button("Next (Space)") || key) lesson.next = true;
      ImGui::SameLine();
      ImGui::TextDisabled("Look around first: every view and parameter still works.");
    } else if (lesson.finished) {
      ImGui::TextDisabled("End of the lesson. The window stays open; Esc quits.");
    }
  }
  ImGui::End();
}

#include "window/script/ui_lesson.h"

#include <imgui.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "window/ui_state.h"

namespace {
bool lessonShown(const LessonState& lesson) { return !lesson.text.empty() || !lesson.title.empty(); }
}  // namespace

float lessonPanelHeight(const UiState& state) {
  if (!lessonShown(state.lesson)) return 0;
  const ImGuiStyle& style = ImGui::GetStyle();
  return 2 * style.WindowPadding.y + ImGui::GetFrameHeightWithSpacing() +
         float(kLessonTextLines) * ImGui::GetTextLineHeightWithSpacing();
}

void drawLessonWindow(UiState& state, float x, float y, float width, float height) {
  LessonState& lesson = state.lesson;
  if (!lessonShown(lesson)) return;
  ImGui::SetNextWindowPos({x, y}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({width, height}, ImGuiCond_Always);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoBringToFrontOnFocus |
                                 ImGuiWindowFlags_NoTitleBar;
  // No title bar: a title bar cuts a long title; the title is the text's first lines.
  if (ImGui::Begin("###lesson", nullptr, flags)) {
    // 1. The step and the button first, so a long text that scrolls never hides them.
    if (lesson.steps > 0) {
      ImGui::TextColored({0.95f, 0.8f, 0.4f, 1}, "Step %d of %d", lesson.step, lesson.steps);
      ImGui::SameLine();
    }
    if (lesson.waiting) {
      const bool key = !ImGui::GetIO().WantTextInput &&
                       (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false) || ImGui::IsKeyPressed(GLFW_KEY_N, false));
      if (ImGui::Button("Next (Space)") || key) lesson.next = true;
      ImGui::SameLine();
      ImGui::PushTextWrapPos(0);
      ImGui::TextDisabled("Look around first: every view and parameter still works.");
      ImGui::PopTextWrapPos();
    } else if (lesson.finished) {
      ImGui::PushTextWrapPos(0);
      ImGui::TextDisabled("End of the lesson. The window stays open; Ctrl+Q quits.");
      ImGui::PopTextWrapPos();
    } else {
      ImGui::NewLine();
    }
    // 2. The title and the text, wrapped to the strip; they scroll when longer than the strip.
    ImGui::BeginChild("##lesson_text");
    ImGui::PushTextWrapPos(0);
    ImGui::TextColored({0.95f, 0.8f, 0.4f, 1}, "Lesson: %s", lesson.title.empty() ? "(untitled)" : lesson.title.c_str());
    ImGui::TextUnformatted(lesson.text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndChild();
  }
  ImGui::End();
}

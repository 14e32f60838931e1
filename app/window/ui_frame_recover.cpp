#include "window/ui_frame_recover.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <cstdarg>
#include <cstdio>

namespace {

void collect(void* userData, const char* format, ...) {
  auto* lines = static_cast<std::string*>(userData);
  char line[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(line, sizeof line, format, args);
  va_end(args);
  if (lines) *lines += std::string(line) + "\n";
}

}  // namespace

// ImGui::ErrorCheckEndFrameRecover in 1.86 ends `g.CurrentTabBar` from whichever window is
// current: thrown inside a popup opened in a tab (the side panel's tabs hold combos), it
// would end the outer window's tab bar from the popup and fail an assertion on the popup's ID
// stack. So the windows are closed here one by one, innermost first, each ending only the
// tab bars it began (a tab bar pushes its ID onto its own window's ID stack) and leaving the
// outer ones to their windows.
bool closeInterruptedFrame(std::string* recovered) {
  ImGuiContext* context = ImGui::GetCurrentContext();
  if (!context || !context->WithinFrameScope) return false;
  ImGuiContext& g = *context;
  for (int guard = 0; g.CurrentWindowStack.Size > 1 && guard < 1000; ++guard) {
    ImGuiWindow* window = g.CurrentWindow;
    for (int tabBars = 0; g.CurrentTabBar && window->IDStack.contains(g.CurrentTabBar->ID) && tabBars < 100; ++tabBars) {
      collect(recovered, "Recovered from missing EndTabBar() in '%s'", window->Name);
      ImGui::EndTabBar();
    }
    ImGuiTabBar* outer = g.CurrentTabBar;
    g.CurrentTabBar = nullptr;
    ImGui::ErrorCheckEndWindowRecover(collect, recovered);
    g.CurrentTabBar = outer;
    if (window->Flags & ImGuiWindowFlags_ChildWindow) {
      collect(recovered, "Recovered from missing EndChild() for '%s'", window->Name);
      ImGui::EndChild();
    } else {
      collect(recovered, "Recovered from missing End() for '%s'", window->Name);
      ImGui::End();
    }
  }
  ImGui::ErrorCheckEndFrameRecover(collect, recovered);  // what is left on the fallback window
  ImGui::Render();
  return true;
}

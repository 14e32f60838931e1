#include "window/ui_layout_report.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "window/views/ui_view_colorbar.h"

void printLayout(const std::string& label) {
  const ImGuiContext& context = *ImGui::GetCurrentContext();
  for (const ImGuiWindow* window : context.Windows) {
    if (!window->WasActive || window->Hidden) continue;  // not drawn in the last frame
    // Whole pixels: ImGui rounds text widths up to whole pixels, and panel edges may lie
    // between pixels, so a line that fits can reach up to one pixel past a fractional edge.
    const float overflow = std::floor(std::max(0.0f, window->DC.CursorMaxPos.x - window->WorkRect.Max.x));
    std::printf("layout %s: window %s at %.0f %.0f size %.0f %.0f contents %.0f %.0f overflow %.0f\n",
                label.c_str(), window->Name, window->Pos.x, window->Pos.y, window->Size.x,
                window->Size.y, window->ContentSize.x, window->ContentSize.y, overflow);
  }
  printColorBars(label);
  std::fflush(stdout);
}

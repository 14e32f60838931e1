#include "window/ui_layout.h"

#include <imgui.h>

#include <algorithm>

Layout layoutFor(float width, float height, float uiScale, float lessonHeight, float timelineHeight) {
  Layout layout{width, height, std::clamp(width * 0.27f, 220.0f * uiScale, 360.0f * uiScale),
                std::clamp(width * 0.23f, 220.0f * uiScale, 330.0f * uiScale), ImGui::GetFrameHeight() + 6,
                0, false};
  // One pixel of slack: at the panels' own shares (0.27 + 0.23) the views get exactly half.
  if (layout.centerWidth() < kMinViewsShare * width - 1) {
    layout.stacked = true;
    layout.right = 0;
  }
  layout.lesson = std::min(lessonHeight, 0.35f * layout.panelHeight());
  layout.timeline = std::min(timelineHeight, 0.15f * layout.panelHeight());
  return layout;
}

#include "ui_trace_panel.h"

#include <imgui.h>

#include <algorithm>

RayTraceSource& rayTraceSource() {
  static RayTraceSource source;
  return source;
}

// Level colours: a small categorical ramp, repeating past 8 levels.
unsigned levelColor(int level) {
  static const ImU32 colors[8] = {IM_COL32(250, 220, 90, 255),  IM_COL32(90, 210, 220, 255),
                                  IM_COL32(60, 200, 90, 255),   IM_COL32(240, 150, 60, 255),
                                  IM_COL32(160, 90, 220, 255),  IM_COL32(220, 60, 60, 255),
                                  IM_COL32(40, 110, 230, 255),  IM_COL32(200, 200, 200, 255)};
  return level < 0 ? IM_COL32(235, 235, 235, 255) : colors[level % 8];  // -1: linear samples
}

namespace {

// 1. The plot: x = step, y = light depth (0 at the top: nearer the light). Each step draws
//    its neighbourhood's [zNearMin, zFarMax] band and the ray's
//    depth over the step as a white segment: where the segment enters the band, the ray may
//    be blocked there.
void drawPlot(const std::vector<RayStepRecord>& steps) {
  const ImVec2 size{ImGui::GetContentRegionAvail().x, 140};
  const ImVec2 at = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(at, {at.x + size.x, at.y + size.y}, IM_COL32(20, 20, 24, 255));
  float low = 1, high = 0;
  for (const RayStepRecord& s : steps) {
    low = std::min({low, s.rayDepthEnter, s.rayDepthExit});
    high = std::max({high, s.rayDepthEnter, s.rayDepthExit});
    if (s.level >= 0 && s.zNearMin <= s.zFarMax) {
      low = std::min(low, s.zNearMin);
      high = std::max(high, s.zFarMax);
    }
  }
  if (high <= low) high = low + 1;
  const auto y = [&](float depth) { return at.y + 4 + (depth - low) / (high - low) * (size.y - 8); };
  const float column = size.x / float(std::max<size_t>(steps.size(), 1));
  for (size_t i = 0; i < steps.size(); ++i) {
    const RayStepRecord& s = steps[i];
    const float x0 = at.x + column * float(i), x1 = x0 + column;
    const ImU32 color = levelColor(s.level);
    if (s.level >= 0 && s.zNearMin <= s.zFarMax) {
      draw->AddRectFilled({x0 + 1, y(s.zNearMin)}, {x1 - 1, y(s.zFarMax)}, (color & 0x00ffffff) | 0x60000000);
      draw->AddRect({x0 + 1, y(s.zNearMin)}, {x1 - 1, y(s.zFarMax)}, color);
    }
    draw->AddLine({x0, y(s.rayDepthEnter)}, {x1, y(s.rayDepthExit)}, IM_COL32_WHITE, 2);
  }
  ImGui::Dummy(size);
  ImGui::TextDisabled("x: step; y: light depth (down: farther). Bands: zNearMin..zFarMax of\n"
                      "the visited window, coloured by level; white: the ray's depth.");
}

// 2. The step table.
void drawTable(const std::vector<RayStepRecord>& steps) {
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY |
                                ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
  if (!ImGui::BeginTable("steps", 6, flags, {0, 200})) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  for (const char* name : {"#", "lvl", "window", "ray depth", "zNearMin..zFarMax", "decision"})
    ImGui::TableSetupColumn(name);
  ImGui::TableHeadersRow();
  for (size_t i = 0; i < steps.size(); ++i) {
    const RayStepRecord& s = steps[i];
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::Text("%zu", i);
    ImGui::TableNextColumn();
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(levelColor(s.level)), "%d", s.level);
    ImGui::TableNextColumn();
    ImGui::Text("%d,%d-%d,%d", s.windowLo.x, s.windowLo.y, s.windowHi.x, s.windowHi.y);
    ImGui::TableNextColumn();
    ImGui::Text("%.4f-%.4f", s.rayDepthEnter, s.rayDepthExit);
    ImGui::TableNextColumn();
    ImGui::Text("%.4f..%.4f", s.zNearMin, s.zFarMax);
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(s.decision.c_str());
  }
  ImGui::EndTable();
}

}  // namespace

// 3. Summary, plot, table; the visited windows become rectangles over light-sized views.
void drawRayTracePanel(const RayTraceInfo& trace, glm::ivec2 lightMapSize,
                       std::vector<ViewOverlayShape>& overlay) {
  ImGui::Text("%zu steps%s%s", trace.steps.size(), trace.result.empty() ? "" : ", ",
              trace.result.c_str());
  if (trace.steps.empty()) return;
  glm::vec2 previous{-1};
  for (const RayStepRecord& s : trace.steps) {
    if (s.windowLo.x >= 0)
      overlay.push_back({lightMapSize, glm::vec2(s.windowLo), glm::vec2(s.windowHi + 1),
                         levelColor(s.level), false});
    if (s.texelPoint.x >= 0 && previous.x >= 0)
      overlay.push_back({lightMapSize, previous, s.texelPoint, 0xffffffffu, true});
    if (s.texelPoint.x >= 0) previous = s.texelPoint;
  }
  drawPlot(trace.steps);
  drawTable(trace.steps);
}

#include "window/views/ui_view_colorbar.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "io/colormap.h"
#include "window/ui_state.h"
#include "window/ui_widgets.h"
#include "window/views/ui_view_difference.h"

namespace {

std::string number(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", double(value));
  return text;
}

int viewIndex(const UiState& state, const ViewPanel& view) {
  for (int i = 0; i < kMaxViews; ++i)
    if (&state.views.panels[i] == &view) return i;
  return 0;
}

}  // namespace

std::string colorBarLabel(const UiState& state, const ViewPanel& view, const GlTexture& texture) {
  const int channel = singleChannel(view.settings, texture.channelCount());
  if (channel < 0 || view.settings.colormap == Colormap::Categorical) return "";
  const std::vector<std::string> names = shownChannelNames(state, view);
  const std::string channelName =
      channel < int(names.size()) ? names[size_t(channel)] : std::string(1, "RGBA"[channel]);
  return view.output + (view.minus.empty() ? "" : " - " + view.minus) + ": " + channelName +
         (view.settings.autoRange ? " · auto range (p99)" : "");
}

void updateAutoRange(const UiState& state, ViewPanel& view, const GlTexture& texture) {
  view.renderer.autoRange(texture, view.settings, state.session.pipelineRuns);
}

void drawViewColorBar(UiState& state, const ViewPanel& view, const GlTexture& texture,
                      glm::vec2 origin, glm::vec2 regionSize) {
  DrawnColorBars& drawn = state.panelMemory.colorBars;
  if (drawn.frame != ImGui::GetFrameCount()) {
    drawn.bars.clear();
    drawn.frame = ImGui::GetFrameCount();
  }
  const std::string label = colorBarLabel(state, view, texture);
  if (label.empty()) return;
  const ViewSettings& s = view.settings;
  const std::string low = number(s.black), high = number(s.white);
  // A dark box at the bottom of the region: values on the ends, the label under the bar.
  const float pad = uiPixels(4), line = ImGui::GetTextLineHeight();
  const float labelWidth = ImGui::CalcTextSize(label.c_str()).x;
  const float width = std::min(regionSize.x - 2 * pad, std::max(uiPixels(260), labelWidth + 2 * pad));
  if (width < uiPixels(80) || regionSize.y < 3 * line + 4 * pad) return;  // no room: none
  const float height = pad + uiPixels(10) + pad + line + pad + line + pad;
  const ImVec2 box{origin.x + pad, origin.y + regionSize.y - pad - height};
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect({origin.x, origin.y}, {origin.x + regionSize.x, origin.y + regionSize.y}, true);
  draw->AddRectFilled(box, {box.x + width, box.y + height}, IM_COL32(16, 16, 20, 210), uiPixels(3));
  const float x0 = box.x + pad, x1 = box.x + width - pad, barTop = box.y + pad;
  const float barBottom = barTop + uiPixels(10);
  const int steps = std::max(2, int(x1 - x0));
  for (int i = 0; i < steps; ++i) {
    const float t = float(i) / float(steps - 1);
    const auto c = applyColormap(s.colormap, t, s.black + t * (s.white - s.black));
    const float a = x0 + (x1 - x0) * float(i) / float(steps), b = x0 + (x1 - x0) * float(i + 1) / float(steps);
    draw->AddRectFilled({a, barTop}, {b + 0.5f, barBottom}, IM_COL32(c[0], c[1], c[2], 255));
  }
  draw->AddRect({x0, barTop}, {x1, barBottom}, IM_COL32(200, 200, 200, 255));
  const ImU32 text = IM_COL32(235, 235, 235, 255);
  const float ticks = barBottom + pad;
  draw->AddText({x0, ticks}, text, low.c_str());
  draw->AddText({x1 - ImGui::CalcTextSize(high.c_str()).x, ticks}, text, high.c_str());
  const std::string middle = number(0.5f * (s.black + s.white));
  const float middleWidth = ImGui::CalcTextSize(middle.c_str()).x;
  const float middleX = 0.5f * (x0 + x1) - 0.5f * middleWidth;
  if (middleX > x0 + ImGui::CalcTextSize(low.c_str()).x + pad &&
      middleX + middleWidth < x1 - ImGui::CalcTextSize(high.c_str()).x - pad)
    draw->AddText({middleX, ticks}, text, middle.c_str());
  draw->AddText({x0, ticks + line + pad}, text, label.c_str());  // clipped to the region if long
  draw->PopClipRect();
  drawn.bars.push_back({viewIndex(state, view), {box.x, box.y}, {width, height}, s.black, s.white,
                        s.autoRange, label});
}

void printColorBars(const UiState& state, const std::string& label) {
  const DrawnColorBars& drawn = state.panelMemory.colorBars;
  if (drawn.frame != ImGui::GetFrameCount() && drawn.frame != ImGui::GetFrameCount() - 1) return;
  for (const DrawnColorBar& bar : drawn.bars)
    std::printf("layout %s: colorbar %c at %.0f %.0f size %.0f %.0f range %.6g %.6g auto %d label %s\n",
                label.c_str(), "ABCD"[bar.view], bar.min.x, bar.min.y, bar.size.x, bar.size.y,
                double(bar.low), double(bar.high), bar.automatic ? 1 : 0, bar.label.c_str());
  std::fflush(stdout);
}

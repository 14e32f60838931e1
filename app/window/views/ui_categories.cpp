#include "window/views/ui_categories.h"

#include <imgui.h>

#include <cstdio>

#include "io/colormap.h"
#include "window/ui_state.h"

// The legend, counted once per pipeline run and view content.
void drawCategoryLegend(const UiState& state, const ViewPanel& view) {
  if (!state.session.frame || !state.session.frame->has(view.output)) return;
  const GlTexture& texture = state.session.frame->texture(view.output);
  const int channel = singleChannel(view.settings, texture.channelCount());
  if (channel < 0 || view.settings.colormap != Colormap::Categorical) return;
  std::map<int, long>& counts = view.categories.counts;
  const std::string key = std::to_string(state.session.pipelineRuns) + view.output + "/" +
                          std::to_string(view.settings.layer) + "/" + std::to_string(channel);
  if (key != view.categories.key) {
    counts = categoryCounts(texture.readFloats(texture.isArray() ? view.settings.layer : 0),
                            texture.channelCount(), channel);
    view.categories.key = key;
  }
  const Output* output = state.session.outputOf(view.output);
  const auto names = categoryNamesFromDoc(output ? output->doc : "");
  const double total = double(texture.width()) * texture.height();
  ImGui::TextDisabled("%s", view.output.c_str());
  // Swatch and name, then count and share right-aligned; below the name when the panel is too
  // narrow for both (large UI scale), so nothing is cut.
  const float swatch = ImGui::GetTextLineHeight() * 0.9f;
  for (const auto& [value, count] : counts) {
    const auto rgb = applyColormap(Colormap::Categorical, 0, float(value));
    ImGui::ColorButton(("##c" + std::to_string(value)).c_str(),
                       ImVec4(rgb[0] / 255.0f, rgb[1] / 255.0f, rgb[2] / 255.0f, 1),
                       ImGuiColorEditFlags_NoTooltip, {swatch, swatch});
    ImGui::SameLine();
    const auto name = names.find(value);
    ImGui::Text("%d %s", value, name != names.end() ? name->second.c_str() : "");
    char share[48];
    std::snprintf(share, sizeof share, "%ld  %5.1f%%", count, 100.0 * double(count) / total);
    const float x = ImGui::GetContentRegionMax().x - ImGui::CalcTextSize(share).x;
    const float nameEnd = ImGui::GetItemRectMax().x - ImGui::GetWindowPos().x;
    if (nameEnd + ImGui::GetStyle().ItemSpacing.x <= x) ImGui::SameLine(x);
    else ImGui::SetCursorPosX(x);
    ImGui::TextUnformatted(share);
  }
}

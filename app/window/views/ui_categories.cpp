#include "window/views/ui_categories.h"

#include <imgui.h>

#include "io/colormap.h"
#include "window/ui_state.h"

// The legend, counted once per pipeline run and view content.
void drawCategoryLegend(const UiState& state, const ViewPanel& view) {
  if (!state.session.frame || !state.session.frame->has(view.output)) return;
  const GlTexture& texture = state.session.frame->texture(view.output);
  const int channel = singleChannel(view.settings, texture.channelCount());
  if (channel < 0 || view.settings.colormap != Colormap::Categorical) return;
  static std::map<int, long> counts;
  static std::string cachedKey;
  const std::string key = std::to_string(state.session.pipelineRuns) + view.output + "/" +
                          std::to_string(view.settings.layer) + "/" + std::to_string(channel);
  if (key != cachedKey) {
    counts = categoryCounts(texture.readFloats(texture.isArray() ? view.settings.layer : 0),
                            texture.channelCount(), channel);
    cachedKey = key;
  }
  const Output* output = state.session.outputOf(view.output);
  const auto names = categoryNamesFromDoc(output ? output->doc : "");
  const double total = double(texture.width()) * texture.height();
  ImGui::TextDisabled("%s", view.output.c_str());
  for (const auto& [value, count] : counts) {
    const auto rgb = applyColormap(Colormap::Categorical, 0, float(value));
    ImGui::ColorButton(("##c" + std::to_string(value)).c_str(),
                       ImVec4(rgb[0] / 255.0f, rgb[1] / 255.0f, rgb[2] / 255.0f, 1),
                       ImGuiColorEditFlags_NoTooltip, {12, 12});
    ImGui::SameLine();
    const auto name = names.find(value);
    ImGui::Text("%d %-11s %8ld  %5.1f%%", value, name != names.end() ? name->second.c_str() : "",
                count, 100.0 * double(count) / total);
  }
}

#include "window/views/ui_view_toolbar.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "window/panels/ui_export.h"
#include "window/views/ui_view_difference.h"
#include "window/ui_graph.h"
#include "window/ui_state.h"
#include "window/ui_widgets.h"

// 1. Autofit reads back only the visible rectangle.
void autofitView(ViewPanel& view, const GlTexture& texture) {
  glm::ivec2 lo{0, 0}, hi{texture.width(), texture.height()};  // about to fit: everything
  if (!view.fitPending)
    view.transform.visibleTexels(view.regionSize, {texture.width(), texture.height()}, lo, hi);
  const std::vector<float> values =
      readRegion(texture, lo.x, lo.y, hi.x - lo.x, hi.y - lo.y, view.settings.layer);
  float low = 0, high = 1;
  if (!finiteRange(values, texture.channelCount(), view.settings, low, high)) return;
  if (view.settings.colormap == Colormap::Diverging) {  // signed data: white stays at 0
    high = std::max(std::abs(low), std::abs(high));
    low = -high;
  }
  if (high - low < 1e-12f * std::max(1.0f, std::abs(low))) {  // constant: centre it
    low -= 0.5f;
    high += 0.5f;
  }
  view.settings.black = low;
  view.settings.white = high;
  view.settings.autoRange = false;  // the user's range from now on
}

void resetView(UiState& state, ViewPanel& view, const GlTexture& texture) {
  const Output* output = state.session.outputOf(view.output);
  if (!output) return;
  const int layer = view.settings.layer;
  view.settings = defaultViewSettings(*output, texture.channelCount());
  view.settings.layer = layer;
}

namespace {

// 2a. "minus": the difference view (app/window/views/ui_view_difference.h), with the thickness preset.
void drawDifferenceControls(UiState& state, ViewPanel& view) {
  sameLineIfFits(170);
  ImGui::SetNextItemWidth(uiPixels(130));
  const std::string current =
      view.minus.empty() ? "- (nothing)" : "- " + comboPreview(view.minus, uiPixels(130) - ImGui::CalcTextSize("- ").x);
  if (ImGui::BeginCombo("##minus", current.c_str())) {
    if (ImGui::Selectable("- (nothing): the output itself", view.minus.empty()))
      setViewDifference(state, view, "");
    if (!layerOutputs(state.session.pipeline).far.empty() && ImGui::Selectable("thickness: far - near"))
      state.fail("view", showThickness(state));
    const GlTexture* a = state.session.frame && state.session.frame->has(view.output) ? &state.session.frame->texture(view.output) : nullptr;
    for (const std::string& key : state.session.outputKeys()) {
      if (key == view.output || !a || !state.session.frame->has(key)) continue;
      const GlTexture& b = state.session.frame->texture(key);
      if (b.width() != a->width() || b.height() != a->height()) continue;
      if (ImGui::Selectable(("- " + key).c_str(), key == view.minus))
        state.fail("view", setViewDifference(state, view, key));
    }
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s%sDifference view: this output minus another of the same size, in the\n"
                      "diverging colormap (red: this one is larger). 'thickness': far - near\n"
                      "light layer, the occluders' extent along the light (thesis §3.3).",
                      view.minus.empty() ? "" : ("- " + view.minus).c_str(), view.minus.empty() ? "" : "\n\n");
  if (view.minus.empty()) return;
  ImGui::SameLine();
  ImGui::Checkbox("neg->0", &view.clipNegative);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Show negative differences as 0. For far - near these are exactly the\n"
                      "texels no occluder covers (far cleared to 0, near to 1).");
}

// 2. Line 1: what is shown (output, lock, channels, colormap, level). Returns whether the
//    output changed: the texture the view was drawn with so far is then the old output's,
//    and the new one has usually not been run yet (demand-driven runs), so the rest of the
//    toolbar waits for the next frame.
bool drawOutputCombo(UiState& state, ViewPanel& view, float width) {
  bool changed = false;
  ImGui::SetNextItemWidth(width);
  if (ImGui::BeginCombo("##output", comboPreview(view.output, width).c_str())) {
    for (const std::string& key : state.session.outputKeys())
      if (ImGui::Selectable(key.c_str(), key == view.output)) {
        changed = key != view.output || !view.minus.empty();
        view.output = key;
        view.fitPending = true;
        setViewDifference(state, view, "");
        changed = true;
      }
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", view.output.c_str());  // the preview may be cut
  return changed;
}

// Returns whether the output changed (drawOutputCombo).
bool drawSourceControls(UiState& state, ViewPanel& view, const GlTexture* texture) {
  if (drawOutputCombo(state, view, std::clamp(ImGui::GetContentRegionAvail().x - uiPixels(170), uiPixels(120), uiPixels(210))))
    return true;
  sameLineIfFits(60);
  ImGui::Checkbox("lock", &view.locked);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("A locked view keeps its output when stages are selected on the left.");
  drawDifferenceControls(state, view);
  if (!texture) return false;
  // Channel toggles as small buttons, lit when on.
  const char* names[4] = {"R", "G", "B", "A"};
  const ImVec4 lit[4] = {{0.75f, 0.2f, 0.2f, 1}, {0.2f, 0.6f, 0.25f, 1}, {0.25f, 0.35f, 0.8f, 1},
                         {0.55f, 0.55f, 0.55f, 1}};
  for (int c = 0; c < std::min(texture->channelCount(), 4); ++c) {
    if (c == 0) sameLineIfFits(26.0f * float(std::min(texture->channelCount(), 4)));
    else ImGui::SameLine(0, 2);
    const bool on = view.settings.channels[size_t(c)];
    ImGui::PushStyleColor(ImGuiCol_Button, on ? lit[c] : ImVec4(0.2f, 0.2f, 0.22f, 1));
    if (ImGui::Button(names[c], {uiPixels(22), 0})) view.settings.channels[size_t(c)] = !on;
    ImGui::PopStyleColor();
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Channel %s on/off. One channel alone: shown through the colormap.", names[c]);
  }
  const bool single = singleChannel(view.settings, texture->channelCount()) >= 0;
  sameLineIfFits(100);
  ImGui::SetNextItemWidth(uiPixels(100));
  ImGui::BeginDisabled(!single);
  int map = int(view.settings.colormap);
  const auto maps = colormapNames();
  if (ImGui::BeginCombo("##colormap", maps[size_t(map)].c_str())) {
    for (int m = 0; m < int(maps.size()); ++m)
      if (ImGui::Selectable(maps[size_t(m)].c_str(), m == map)) view.settings.colormap = Colormap(m);
    ImGui::EndCombo();
  }
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("Colormap for a single channel (colour shows each channel in gray).");
  // The output's own texture (a difference view is 2D); read only where this run wrote it.
  const Frame* frame = state.session.frame.get();
  const GlTexture* source = frame && frame->has(view.output) ? &frame->texture(view.output) : nullptr;
  if (source && source->isArray()) {
    sameLineIfFits(170);
    ImGui::SetNextItemWidth(uiPixels(110));
    ImGui::SliderInt("level", &view.settings.layer, 0, source->layers() - 1);
    helpMarker("Array layer: for the N-buffer, level n holds min/max over 2^n x 2^n texels.");
  } else if (source && source->levels() > 1) {
    sameLineIfFits(170);
    ImGui::SetNextItemWidth(uiPixels(110));
    ImGui::SliderInt("mip", &view.settings.layer, 0, source->levels() - 1);
    helpMarker("Mip level, shown at its own size: for the min-max mipmap, mip m is level m + 1, "
               "min/max over aligned 2^(m+1) x 2^(m+1) texels of the light layers (level 0 is "
               "the layers). The base is padded to a power of two; the padding reads 0.");
  }
  return false;
}

// 3. Line 2: the value range, overlay, zoom, exports.
void drawRangeControls(UiState& state, ViewPanel& view, const GlTexture& texture) {
  ViewSettings& s = view.settings;
  const float speed = std::max(1e-6f, std::abs(s.white - s.black) * 0.005f);
  ImGui::SetNextItemWidth(uiPixels(80));
  if (ImGui::DragFloat("##black", &s.black, speed, 0, 0, "%.4g")) s.autoRange = false;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Black point: drag, or double-click to type.");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(uiPixels(80));
  if (ImGui::DragFloat("##white", &s.white, speed, 0, 0, "%.4g")) s.autoRange = false;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("White point: drag, or double-click to type.");
  sameLineIfFits(60);
  if (ImGui::Button("Autofit")) autofitView(view, texture);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Black/white = min/max of the visible texels (A)");
  ImGui::SameLine();
  if (ImGui::Button("Reset")) resetView(state, view, texture);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("The stage's declared range and colormap (R)");
  sameLineIfFits(60);
  ImGui::Checkbox("NaN", &s.overlay);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Overlay: NaN magenta, Inf green, negative blue (shown channels).");
  sameLineIfFits(140);
  if (ImGui::Button("Fit")) view.fitPending = true;
  ImGui::SameLine();
  if (ImGui::Button("1:1")) {
    view.transform.oneToOne();
    view.fitted = false;
  }
  ImGui::SameLine();
  ImGui::TextDisabled("%.0f%%", view.transform.zoom * 100);
  sameLineIfFits(90);
  if (ImGui::Button("PNG")) state.reportExport(exportViewFiles(state, view, "", ExportKind::Png));
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Export this view as displayed (PNG)");
  ImGui::SameLine();
  if (ImGui::Button("EXR")) state.reportExport(exportViewFiles(state, view, "", ExportKind::Exr));
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Export this view's raw values (EXR)");
}

}  // namespace

// 4. Both lines; the second only once the output has a texture. Compact: one line.
void drawViewToolbar(UiState& state, ViewPanel& view, const GlTexture* texture, bool compact) {
  if (compact && !view.toolsOpen) {
    drawOutputCombo(state, view, ImGui::GetContentRegionAvail().x - buttonsWidth({"..."}));
  } else if (!drawSourceControls(state, view, texture) && texture) {
    drawRangeControls(state, view, *texture);
  }
  if (!compact) return;
  ImGui::SameLine();
  if (ImGui::Button(view.toolsOpen ? "^" : "...")) view.toolsOpen = !view.toolsOpen;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip(view.toolsOpen ? "Hide this view's tools" : "This view's tools: lock, difference, channels, colormap, range, zoom, export");
}

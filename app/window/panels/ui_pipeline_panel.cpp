#include "window/panels/ui_pipeline_panel.h"

#include <imgui.h>

#include <cstdio>

#include "window/panels/ui_reference_progress.h"
#include "window/ui_state.h"
#include "window/views/ui_view_difference.h"
#include "window/ui_widgets.h"

namespace {

// 1. An output line: selectable, marked with the view(s) showing it, format and size.
void drawOutput(UiState& state, const Stage& stage, const Output& output) {
  const std::string key = stage.name() + "." + output.name;
  std::string shownIn;
  for (int v = 0; v < (state.twoViews ? 2 : 1); ++v)
    if (state.views[v].output == key) shownIn += v == 0 ? "[A]" : "[B]";
  std::string size = "not written";
  if (state.frame && state.frame->has(key)) {
    const GlTexture& texture = state.frame->texture(key);
    char text[64];
    std::snprintf(text, sizeof text, "%dx%d%s", texture.width(), texture.height(),
                  texture.isArray() ? (" x" + std::to_string(texture.layers())).c_str() : "");
    size = text;
  }
  const std::string label = "  " + output.name + "  " + shownIn + "###" + key;
  if (ImGui::Selectable(label.c_str(), !shownIn.empty())) {
    if (ImGui::GetIO().KeyCtrl) {  // Ctrl+click: the other view, opening it if needed
      state.twoViews = true;
      state.activeView = 1 - state.activeView;
    }
    if (std::string problem = state.selectOutput(key); !problem.empty()) state.status = problem;
    state.scrollToStage.clear();  // clicked here: it is in view already
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s\n%s, %s\nclick: show in the active view; Ctrl+click: the other view",
                      output.doc.c_str(), formatName(output.format), size.c_str());
  ImGui::SameLine(ImGui::GetContentRegionMax().x - 110);
  ImGui::TextDisabled("%s %s", formatName(output.format), size.c_str());
}

// 1b. Stage-specific view (issue 4): the light layers' difference, far - near, where covered.
void drawThicknessLine(UiState& state) {
  bool shown = false;
  for (int v = 0; v < (state.twoViews ? 2 : 1); ++v)
    shown |= state.views[v].output == "light_layers.far" && state.views[v].minus == "light_layers.near";
  if (ImGui::Selectable("  thickness (far - near)###light_layers.thickness", shown)) {
    state.status = showThickness(state);
    state.scrollToStage.clear();
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("The occluders' extent along the light: far - near where both layers are\n"
                      "covered (uncovered texels shown as 0), diverging colormap (thesis §3.3,\n"
                      "Fig 3.4). A difference view: any two outputs can be subtracted in a view's\n"
                      "'-' menu.");
}

// 2. A stage: header with number, name and median ms; body with summary and parameters.
void drawStage(UiState& state, Stage& stage, int number) {
  char header[160];
  std::snprintf(header, sizeof header, "%d. %s###stage_%s", number, stage.name().c_str(),
                stage.name().c_str());
  const bool selected = state.selectedStage == stage.name();
  if (selected) ImGui::PushStyleColor(ImGuiCol_Header, ImGui::GetStyleColorVec4(ImGuiCol_HeaderActive));
  if (state.scrollToStage == stage.name()) {  // selected elsewhere: show it at the top
    ImGui::SetNextItemOpen(true);
    ImGui::SetScrollHereY(0.0f);
    state.scrollToStage.clear();
  }
  const bool open = ImGui::CollapsingHeader(header, ImGuiTreeNodeFlags_DefaultOpen);
  if (selected) ImGui::PopStyleColor();
  ImGui::SameLine(ImGui::GetContentRegionMax().x - 64);
  ImGui::Text("%6.1f ms", state.medianStageMs(stage.name()));
  if (!open) return;
  ImGui::PushID(stage.name().c_str());
  ImGui::PushTextWrapPos(0);
  ImGui::TextUnformatted(stage.summary().c_str());
  ImGui::PopTextWrapPos();
  if (!stage.thesisSection().empty()) ImGui::TextDisabled("thesis %s", stage.thesisSection().c_str());
  for (const Output& output : stage.outputs()) drawOutput(state, stage, output);
  if (stage.name() == "light_layers") drawThicknessLine(state);
  ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
  for (Param& param : stage.params())
    if (drawParam(param)) {
      state.dirty = true;
      state.status = stage.name() + "." + param.key + " = " + param.toString();
    }
  ImGui::PopItemWidth();
  if (stage.name() == "reference") drawReferenceProgress(state);  // issue 5
  ImGui::PopID();
  ImGui::Spacing();
}

}  // namespace

// 3. All stages in pipeline order.
void drawPipelinePanel(UiState& state) {
  int number = 1;
  for (const auto& stage : state.pipeline.stages()) drawStage(state, *stage, number++);
}

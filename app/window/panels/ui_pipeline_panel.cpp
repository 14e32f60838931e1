#include "window/panels/ui_pipeline_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "window/panels/ui_hash_stats.h"
#include "window/panels/ui_reference_progress.h"
#include "window/ui_graph.h"
#include "window/ui_state.h"
#include "window/views/ui_view_difference.h"
#include "window/ui_widgets.h"

namespace {

// 1. An output line: selectable, marked with the view(s) showing it, format, size and MiB.
void drawOutput(UiState& state, const Stage& stage, const Output& output) {
  const std::string key = stage.name() + "." + output.name;
  std::string shownIn;
  for (int v = 0; v < state.views.shownViews(); ++v)
    if (state.views.panels[v].output == key) shownIn += std::string("[") + "ABCD"[v] + "]";
  std::string size = state.session.pipeline.lastTime(stage.name()).ran ? "not written" : "not run";
  // Written only where the stages after it read, as nobody showed it (Frame::partial).
  if (state.session.frame && state.session.frame->partial.count(key)) size = "partial (not shown)";
  if (state.session.frame && state.session.frame->has(key)) {
    const GlTexture& texture = state.session.frame->texture(key);
    char text[96];
    std::snprintf(text, sizeof text, "%dx%d%s %.1f MiB", texture.width(), texture.height(),
                  texture.isArray()        ? (" x" + std::to_string(texture.layers())).c_str()
                  : texture.levels() > 1 ? (" +" + std::to_string(texture.levels() - 1) + " mips").c_str()
                                         : "",
                  state.session.frame->megabytes(key));
    size = text;
  }
  const std::string label = "  " + output.name + "  " + shownIn + "###" + key;
  if (ImGui::Selectable(label.c_str(), !shownIn.empty())) {
    if (ImGui::GetIO().KeyCtrl) {  // Ctrl+click: the other view, opening it if needed
      if (state.views.layout == ViewLayout::One) state.views.setLayout(ViewLayout::SideBySide);
      state.views.activeView = (state.views.activeView + 1) % state.views.shownViews();
    }
    if (std::string problem = state.selectOutput(key); !problem.empty()) state.status = problem;
    state.views.scrollToStage.clear();  // clicked here: it is in view already
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s\n%s, %s\nclick: show in the active view; Ctrl+click: the other view",
                      output.doc.c_str(), formatName(output.format), size.c_str());
  // Right-aligned after the name; on its own line when the panel is too narrow for both (never
  // over the name: ssm's "occluderBackMap DEPTH32F" in a narrow panel).
  const std::string info = std::string(formatName(output.format)) + " " + size;
  const float infoX = ImGui::GetContentRegionMax().x - ImGui::CalcTextSize(info.c_str()).x;
  const float nameEnd = ImGui::CalcTextSize(("  " + output.name + "  " + shownIn).c_str()).x +
                        ImGui::GetStyle().ItemSpacing.x;
  const bool below = infoX < nameEnd;
  if (below) ImGui::Indent();
  else ImGui::SameLine(infoX);
  ImGui::PushTextWrapPos(0);
  ImGui::TextDisabled("%s", info.c_str());
  ImGui::PopTextWrapPos();
  if (below) ImGui::Unindent();
}

// 1b. An input slot and the producer wired to it (the graph, as the registry built it):
//     click to show the producer's output.
void drawInput(UiState& state, const Stage& stage, const Input& input) {
  const std::string source = state.session.pipeline.source(stage.name(), input.name);
  std::string label = "  " + input.name + " <- " + (source.empty() ? "(none)" : source);
  if (input.isChoice()) label += "  (" + input.choiceParam + ")";
  if (ImGui::CalcTextSize(label.c_str()).x > ImGui::GetContentRegionAvail().x)  // lines, not cut
    label = "  " + input.name + " <-\n      " + (source.empty() ? "(none)" : source) +
            (input.isChoice() ? "\n      (" + input.choiceParam + ")" : "");
  const bool texture = !source.empty() && state.session.outputOf(source) && !state.session.outputOf(source)->isBuffer();
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  if (ImGui::Selectable((label + "###in_" + stage.name() + "." + input.name).c_str(), false) && texture) {
    if (std::string problem = state.selectOutput(source); !problem.empty()) state.status = problem;
    state.views.scrollToStage.clear();
  }
  ImGui::PopStyleColor();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("input slot '%s': %s\n%s%s", input.name.c_str(), input.doc.c_str(),
                      input.isChoice() ? ("chosen by the parameter " + input.choiceParam + "\n").c_str() : "",
                      texture ? "click: show the producer's output" : "a storage buffer (not viewable)");
}

// 1c. Stage-specific view (docs/design.md#window): the light layers' difference, far - near, where
// covered.
void drawThicknessLine(UiState& state) {
  const LayerOutputs layers = layerOutputs(state.session.pipeline);
  bool shown = false;
  for (int v = 0; v < state.views.shownViews(); ++v)
    shown |= state.views.panels[v].output == layers.far && state.views.panels[v].minus == layers.near;
  if (ImGui::Selectable("  thickness (far - near)###layers.thickness", shown)) {
    state.status = showThickness(state);
    state.views.scrollToStage.clear();
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
  const bool selected = state.views.selectedStage == stage.name();
  if (selected) ImGui::PushStyleColor(ImGuiCol_Header, ImGui::GetStyleColorVec4(ImGuiCol_HeaderActive));
  if (state.views.scrollToStage == stage.name()) {  // selected elsewhere: show it at the top
    ImGui::SetNextItemOpen(true);
    ImGui::SetScrollHereY(0.0f);
    state.views.scrollToStage.clear();
  }
  const bool open = ImGui::CollapsingHeader(header, ImGuiTreeNodeFlags_DefaultOpen);
  if (selected) ImGui::PopStyleColor();
  const StageTime& time = state.session.pipeline.lastTime(stage.name());
  char timeText[32];
  std::snprintf(timeText, sizeof timeText, time.ran ? "%.1f ms" : "not run", time.median);
  ImGui::SameLine(ImGui::GetContentRegionMax().x - ImGui::CalcTextSize(timeText).x -
                  ImGui::GetStyle().FramePadding.x);
  if (time.ran) ImGui::TextUnformatted(timeText);
  else ImGui::TextDisabled("%s", timeText);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s\ntimed with %s; outputs: %.1f MiB", timingText(time).c_str(),
                      state.session.pipeline.timingMethod().c_str(),
                      state.session.frame ? state.session.frame->megabytes(stage) : 0.0);
  if (!open) return;
  ImGui::PushID(stage.name().c_str());
  ImGui::PushTextWrapPos(0);
  ImGui::TextUnformatted(stage.summary().c_str());
  ImGui::PopTextWrapPos();
  ImGui::PushTextWrapPos(0);
  if (!stage.thesisSection().empty()) ImGui::TextDisabled("%s", stage.thesisSection().c_str());
  ImGui::PopTextWrapPos();
  for (const Input& input : stage.inputs()) drawInput(state, stage, input);
  for (const Output& output : stage.outputs()) drawOutput(state, stage, output);
  if (hasLayerOutputs(stage)) drawThicknessLine(state);
  // Controls share one width, leaving room for the longest name and its (?) marker.
  float names = 0;
  for (const Param& param : stage.params()) names = std::max(names, ImGui::CalcTextSize(param.key.c_str()).x);
  const float avail = ImGui::GetContentRegionAvail().x;
  const float rest = avail - names - buttonsWidth({"(?)"}) - ImGui::GetStyle().ItemInnerSpacing.x;
  // A choice's widest text (" (auto)" included) fits its combo; where that leaves too little
  // room beside a long name, drawParam puts the name above.
  float choices = uiPixels(80);
  for (const Param& param : stage.params())
    if (param.type == Param::Type::Enum)
      for (const std::string& option : param.options)
        choices = std::max(choices, ImGui::CalcTextSize((option + " (auto)").c_str()).x +
                                        ImGui::GetFrameHeight() + 2 * ImGui::GetStyle().FramePadding.x);
  ImGui::PushItemWidth(std::min(std::max(rest, choices), std::max(0.55f * avail, choices)));
  for (Param& param : stage.params())
    if (drawParam(param, state.panelMemory.handValues, autoChosenValue(stage.name(), param, state.session.frame.get()))) {
      state.status = stage.name() + "." + param.key + " = " + param.toString();
    }
  ImGui::PopItemWidth();
  const std::string comparison = comparisonOutput(state.session.pipeline);
  if (comparison.rfind(stage.name() + ".", 0) == 0) drawReferenceProgress(state);  // issues 5, 10
  if (stage.name() == "hash_stats") drawHashStatsPanel(state);  // docs/hash_stats.md
  ImGui::PopID();
  ImGui::Spacing();
}

}  // namespace

// 3. All stages in pipeline order.
void drawPipelinePanel(UiState& state) {
  int number = 1;
  for (const auto& stage : state.session.pipeline.stages()) drawStage(state, *stage, number++);
}

#include "window/panels/ui_reference_progress.h"

#include <imgui.h>

#include <cstdio>

#include "reference/reference_trace.h"
#include "window/ui_graph.h"
#include "window/ui_state.h"

std::string compareWithReference(UiState& state) {
  const Stage* truth = groundTruthStage(state.session.pipeline);
  const std::string comparison = comparisonOutput(state.session.pipeline);
  if (!truth || comparison.empty()) return "no ground truth and comparison stage registered";
  if (std::string problem = state.session.setParameter(truth->name() + ".enabled", "true"); !problem.empty())
    return problem;
  if (state.views.layout == ViewLayout::One) state.views.setLayout(ViewLayout::SideBySide);
  state.views.activeView = 1;
  state.views.panels[1].locked = false;
  std::string problem = state.selectOutput(comparison);
  state.views.activeView = 0;  // the method stays where it was, in view A
  return problem;
}

void drawReferenceProgress(UiState& state) {
  if (ImGui::Button("compare with reference")) {
    const std::string problem = compareWithReference(state);
    state.status = problem.empty() ? "ground truth on; view B shows " + comparisonOutput(state.session.pipeline) : problem;
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Enables the exact reference and shows the signed error (method minus\n"
                      "reference) in view B, beside the method in view A.");
  ReferenceProgress& progress = referenceStageProgress();
  if (!progress.running) return;
  const int total = progress.rowsTotal, done = progress.rowsDone;
  const float fraction = total > 0 ? float(done) / float(total) : 0.0f;
  char text[64];
  std::snprintf(text, sizeof text, "tracing rows %d / %d", done, total);
  ImGui::ProgressBar(fraction, {ImGui::GetContentRegionAvail().x - 70, 0}, text);
  ImGui::SameLine();
  if (ImGui::Button(progress.cancel ? "cancelling" : "Cancel")) {
    progress.cancel = true;
    state.status = "reference: cancel requested";
  }
}

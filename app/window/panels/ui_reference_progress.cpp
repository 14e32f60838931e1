#include "window/panels/ui_reference_progress.h"

#include <imgui.h>

#include <cstdio>

#include "reference/reference_trace.h"
#include "window/ui_graph.h"
#include "window/ui_live_truth.h"
#include "window/ui_state.h"

std::string compareWithReference(UiState& state) {
  const std::string comparison = comparisonOutput(state.session.pipeline);
  if (comparison.empty()) return "no comparison stage registered";
  applyLiveTruthRule(state.liveTruth, state.session);  // while automatic: raster4d when interactive, else Embree
  const Stage* truth = groundTruthStage(state.session.pipeline);
  if (!truth) return "no ground truth chosen in " + groundTruthChoiceKey(state.session.pipeline);
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
  if (ImGui::Button("compare with ground truth")) {
    const std::string problem = compareWithReference(state);
    state.status = problem.empty() ? "view B shows " + comparisonOutput(state.session.pipeline) +
                                         " " + liveTruthLine(state.liveTruth, state.session.pipeline)
                                   : problem;
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Enables the ground truth and shows the signed error (method minus\n"
                      "ground truth) in view B, beside the method in view A.");
  // The ground truth in use, and whether the window chose it.
  LiveTruth& truth = state.liveTruth;
  ImGui::PushTextWrapPos(0);
  ImGui::TextDisabled("live error %s", liveTruthLine(state.liveTruth, state.session.pipeline).c_str());
  ImGui::PopTextWrapPos();
  if (ImGui::Checkbox("auto ground truth", &truth.automatic)) {
    if (truth.automatic) applyLiveTruthRule(state.liveTruth, state.session);
    else keepUserTruth(state.liveTruth);
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "On: raster4d (4D rasterization on the GPU) when its predicted time per run is at most\n"
        "%.0f ms (measured on this scene, else estimated from eye pixels x light rows x\n"
        "occluder triangles^0.55), else the Embree reference (CPU, background, cached).\n"
        "Choosing `against` yourself turns this off.\n\n"
        "Both are 'exact' only for their sample grid: raster4d decides every one of its m x m\n"
        "light samples (cell centres) exactly, not the continuous light; the error against it\n"
        "includes the difference between the method's sampling and that grid. Embree with\n"
        "reference.sampling=uniform and the same m traces the very same points.",
        kInteractiveTruthMs);
  ReferenceProgress& progress = referenceStageProgress();
  if (!progress.running) return;
  const int total = progress.tilesTotal, done = progress.tilesDone;
  const float fraction = total > 0 ? float(done) / float(total) : 0.0f;
  char text[64];
  std::snprintf(text, sizeof text, "tracing tiles %d / %d", done, total);
  ImGui::ProgressBar(fraction, {ImGui::GetContentRegionAvail().x - 70, 0}, text);
  ImGui::SameLine();
  if (ImGui::Button(progress.cancel ? "cancelling" : "Cancel")) {
    progress.cancel = true;
    state.status = "reference: cancel requested";
  }
}

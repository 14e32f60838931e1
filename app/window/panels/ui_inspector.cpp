#include "window/panels/ui_inspector.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "gl/renderer_calibration.h"
#include "window/views/ui_categories.h"
#include "window/ui_graph.h"
#include "window/ui_state.h"
#include "window/ui_widgets.h"

namespace {

using PickRow = InspectorMemory::PickRow;

// 1. Read back once per pipeline run and pick, not every UI frame.
const std::vector<PickRow>& pickRows(UiState& state) {
  InspectorMemory& memory = state.panelMemory.inspector;
  std::vector<PickRow>& rows = memory.rows;
  if (memory.rowsRuns == state.session.pipelineRuns && memory.rowsPick == *state.views.pick &&
      memory.rowsSpace == state.views.pickSpace)
    return rows;
  memory.rowsRuns = state.session.pipelineRuns;
  memory.rowsPick = *state.views.pick;
  memory.rowsSpace = state.views.pickSpace;
  rows.clear();
  for (const auto& stage : state.session.pipeline.stages())
    for (const Output& output : stage->outputs()) {
      const std::string key = stage->name() + "." + output.name;
      if (!state.session.frame->has(key)) continue;
      const GlTexture& texture = state.session.frame->texture(key);
      if (texture.width() != state.views.pickSpace.x || texture.height() != state.views.pickSpace.y) continue;
      for (int layer = 0; layer < std::max(texture.layers(), 1); ++layer)
        rows.push_back({texture.isArray() ? key + " L" + std::to_string(layer) : key, output.channels,
                        readTexel(texture, memory.rowsPick.x, memory.rowsPick.y, layer),
                        texture.channelCount()});
    }
  return rows;
}

void drawPick(UiState& state) {
  if (!state.views.pick || !state.session.frame) {
    hintText("Click a view to pick a texel; arrow keys move the pick.");
    return;
  }
  ImGui::Text("(%d, %d) in %dx%d", state.views.pick->x, state.views.pickSpace.y - 1 - state.views.pick->y,
              state.views.pickSpace.x, state.views.pickSpace.y);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Image coordinates: row 0 at the top.");
  // Names in their own column when the longest fits in half the panel, else above the values
  // (a narrow panel, a large UI scale): never cut.
  const std::vector<PickRow>& rows = pickRows(state);
  float nameWidth = 0;
  for (const PickRow& row : rows) nameWidth = std::max(nameWidth, ImGui::CalcTextSize(row.label.c_str()).x);
  const bool twoColumns = nameWidth <= 0.5f * ImGui::GetContentRegionAvail().x;
  if (!ImGui::BeginTable("pick", twoColumns ? 2 : 1, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) return;
  if (twoColumns) ImGui::TableSetupColumn("output", ImGuiTableColumnFlags_WidthFixed, nameWidth);
  ImGui::TableSetupColumn("values", ImGuiTableColumnFlags_WidthStretch);
  for (const PickRow& row : rows) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    if (twoColumns) {
      ImGui::TextUnformatted(row.label.c_str());
      ImGui::TableNextColumn();
    } else {
      ImGui::TextColored({0.95f, 0.8f, 0.4f, 1}, "%s", row.label.c_str());
    }
    std::vector<std::string> pieces;  // "name value", never split
    char value[64];
    for (int c = 0; c < row.channelCount; ++c) {
      const std::string name = size_t(c) < row.channelNames.size() ? row.channelNames[size_t(c)]
                                                                   : std::string(1, "RGBA"[c]);
      std::snprintf(value, sizeof value, "%s %.5g", name.c_str(), row.values[size_t(c)]);
      pieces.push_back(value);
    }
    textPieces(pieces);
  }
  ImGui::EndTable();
}

// 2. Bars: per stage, the median over runs with identical settings (the pipeline starts a
//    new series whenever a parameter, the scene or the eye size changes), and the last run.
void drawTimings(const UiState& state) {
  const std::vector<StageTime>& times = state.session.pipeline.lastTimes();
  double slowest = 1e-3;
  for (const StageTime& time : times) slowest = std::max(slowest, time.ran ? time.median : 0.0);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float width = ImGui::GetContentRegionAvail().x;
  const float labelWidth = std::min(uiPixels(110), width * 0.4f);
  for (const StageTime& time : times) {
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float height = ImGui::GetTextLineHeight();
    const float reserve = ImGui::CalcTextSize("00000.0 ms").x + uiPixels(14);  // the number after the bar
    const float barWidth = time.ran ? float(time.median / slowest) * std::max(width - labelWidth - reserve, 0.0f) : 0;
    draw->AddRectFilled({at.x + labelWidth, at.y + 2}, {at.x + labelWidth + barWidth, at.y + height - 1},
                        IM_COL32(90, 150, 230, 255));
    ImGui::TextUnformatted(time.stage.c_str());
    ImGui::SameLine(labelWidth + barWidth + uiPixels(14));
    if (time.ran) ImGui::Text("%.1f ms", time.median);
    else ImGui::TextDisabled("not run");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", timingText(time).c_str());
  }
  const double total = state.session.medianPipelineMs();
  ImGui::TextWrapped("pipeline %.1f ms (%.1f runs/s)", total, total > 0 ? 1000.0 / total : 0.0);
  ImGui::PushTextWrapPos(0);
  ImGui::TextDisabled("median of %d run(s) with these settings; last run %.1f ms; %s timing",
                      state.session.medianRuns(), state.session.lastPipelineMs(),
                      state.session.pipeline.timingMethod().c_str());
  ImGui::PopTextWrapPos();
}

// 3. Counters the stages reported this frame.
void drawCounters(const UiState& state) {
  if (!state.session.frame || state.session.frame->counters.empty()) {
    hintText("No counters this frame.");
    return;
  }
  char number[32];
  for (const auto& [name, value] : state.session.frame->counters) {
    std::snprintf(number, sizeof number, "%.6g", value);
    textPieces({name, number});
  }
}

// What the parameters set to `auto` chose for this scene and view, and why
// (stages/shared_inputs/light/auto_settings.h; docs/decisions/043-auto-map-resolution.md). Whether there are reasons
// to show.
bool hasAutoReasons(const UiState& state) {
  return state.session.frame && !state.session.frame->autoReasons.empty();
}
// The choices `auto` made; a parameter the user (or a lesson) set by hand overrides its
// choice, so the panel says which ones do not apply.
void drawAutoReasons(const UiState& state) {
  std::string byHand;
  for (const std::string& key : state.session.pipeline.paramKeys()) {
    const Param& param = state.session.pipeline.param(key);
    if (param.allowsAuto && !param.automatic)
      byHand += (byHand.empty() ? "" : ", ") + key + " = " + param.toString();
  }
  if (!byHand.empty())
    ImGui::TextWrapped("Set by hand, so these choices do not apply to it: %s.", byHand.c_str());
  for (const std::string& reason : state.session.frame->autoReasons)
    ImGui::TextWrapped("%s", reason.c_str());
  // The crossovers these choices weighed costs with (gl/renderer_calibration.h).
  ImGui::TextWrapped("Calibration: %s.", activeRendererCalibration().describe().c_str());
  if (ImGui::SmallButton("Measure again")) requestRecalibration();
  ImGui::SameLine();
  helpMarker("Times a few frames of the spheres scene on this renderer (a few seconds) and "
             "caches the crossovers `auto` uses; PENUMBRA_CALIBRATION=fallback uses the "
             "constants instead.");
}

// 4. The ray trace hook: the picked eye pixel, ray i of n x n.
void drawRayTrace(UiState& state) {
  state.views.overlays.clear();
  if (!state.views.traceSource) {
    hintText("No trace source installed (ui_trace_panel.h).");
    return;
  }
  if (!state.views.pick || !state.session.frame ||
      state.views.pickSpace != glm::ivec2(state.session.frame->eyeWidth, state.session.frame->eyeHeight)) {
    hintText("Pick a pixel in an eye-sized view.");
    return;
  }
  // The source may replay a whole ray on the CPU: once per run, pick and ray.
  InspectorMemory& memory = state.panelMemory.inspector;
  RayTraceInfo& trace = memory.trace;
  if (memory.traceRuns != state.session.pipelineRuns || memory.tracePick != *state.views.pick ||
      memory.traceRay != state.views.selectedRay) {
    trace = state.views.traceSource(*state.session.frame, *state.views.pick, state.views.selectedRay);
    describeTraceCommand(state, trace);
    memory.traceRuns = state.session.pipelineRuns;
    memory.tracePick = *state.views.pick;
    memory.traceRay = state.views.selectedRay;
  }
  if (trace.raysPerPixel > 1) {
    ImGui::SetNextItemWidth(-uiPixels(60));
    ImGui::SliderInt("ray", &state.views.selectedRay, 0, trace.raysPerPixel - 1);
  }
  glm::ivec2 lightMap{0};
  const std::string nearLayer = recordingInput(state.session.pipeline, "near");
  if (state.session.frame->has(nearLayer))
    lightMap = {state.session.frame->texture(nearLayer).width(), state.session.frame->texture(nearLayer).height()};
  // The ray's windows over the N-buffer's levels, or over the near layer (min-max mipmap).
  const RayOverlayTarget shown = rayOverlayTarget(state.session.pipeline, state.session.frame.get());
  if (!shown.output.empty() &&
      ImGui::Button(shown.perLevel ? "Show on N-buffer" : "Show on near layer")) {
    if (ViewPanel* target = state.views.selectionTarget();
        target && state.selectOutput(shown.output).empty()) {
      target->frameOverlays = true;
      int finest = 1 << 30;  // the finest level the ray visited (linear samples: level 0)
      for (const RayStepRecord& step : trace.steps)
        if (step.level >= 0) finest = std::min(finest, step.level);
      if (shown.perLevel) target->settings.layer = finest == 1 << 30 ? 0 : finest;
    }
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Show %s in the active view, zoomed onto this ray's visited\n"
                      "windows (hierarchical) or samples (linear).%s", shown.output.c_str(),
                      shown.perLevel ? "" : "\nThe min-max mipmap's cells, in level-0 texels,\n"
                                        "are drawn over the near layer (its level 0).");
  sameLineIfButtonsFit({"[x] own window"});
  ImGui::Checkbox("own window", &state.views.traceWindow);
  if (!state.views.traceWindow) {
    drawRayTracePanel(trace, lightMap, state.views.overlays);
    return;
  }
  // A larger, movable window for the step table.
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos({display.x * 0.28f, display.y * 0.3f}, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize({display.x * 0.4f, display.y * 0.66f}, ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Ray trace of the picked pixel", &state.views.traceWindow)) {
    ImGui::SetNextItemWidth(uiPixels(200));
    ImGui::SliderInt("ray##window", &state.views.selectedRay, 0, std::max(trace.raysPerPixel - 1, 0));
    drawRayTracePanel(trace, lightMap, state.views.overlays);
  }
  ImGui::End();
}

}  // namespace

// 5. Sections, top to bottom.
void drawInspector(UiState& state) {
  if (ImGui::CollapsingHeader("Picked texel", ImGuiTreeNodeFlags_DefaultOpen)) drawPick(state);
  for (int v = 0; v < state.views.shownViews(); ++v) {
    const ViewPanel& view = state.views.panels[v];
    const GlTexture* texture = state.session.frame && state.session.frame->has(view.output) ? &state.session.frame->texture(view.output) : nullptr;
    if (texture && view.settings.colormap == Colormap::Categorical &&
        singleChannel(view.settings, texture->channelCount()) >= 0 &&
        ImGui::CollapsingHeader((std::string("Categories (view ") + "ABCD"[v] + ")").c_str(),
                                ImGuiTreeNodeFlags_DefaultOpen))
      drawCategoryLegend(state, view);
  }
  state.views.traceShown = ImGui::CollapsingHeader("Ray trace", ImGuiTreeNodeFlags_DefaultOpen);
  if (state.views.traceShown) drawRayTrace(state);
  else state.views.overlays.clear();
  if (hasAutoReasons(state) && ImGui::CollapsingHeader("auto: the choices",
                                                       ImGuiTreeNodeFlags_DefaultOpen))
    drawAutoReasons(state);
  if (ImGui::CollapsingHeader("Timings", ImGuiTreeNodeFlags_DefaultOpen)) drawTimings(state);
  if (ImGui::CollapsingHeader("Counters", ImGuiTreeNodeFlags_DefaultOpen)) drawCounters(state);
}

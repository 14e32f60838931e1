#include "window/panels/ui_temporal.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <map>
#include <string>
#include <vector>

#include "core/pipeline.h"
#include "reference/error_metrics.h"
#include "stats/temporal.h"
#include "window/ui_graph.h"
#include "window/ui_state.h"
#include "window/ui_widgets.h"

namespace {


void clearPoints(TemporalPanelState& panel) {
  panel.series.clear();
  panel.truthChange.clear();
  panel.previousTruth.clear();
  panel.previousCounted.clear();
}

bool ranLastRun(const Pipeline& pipeline, const std::string& stageDotOutput) {
  const std::string stage = stageDotOutput.substr(0, stageDotOutput.find('.'));
  for (const StageTime& time : pipeline.lastTimes())
    if (time.stage == stage) return time.ran;
  return false;
}

std::string stageOf(const std::string& stageDotOutput) {
  return stageDotOutput.substr(0, stageDotOutput.find('.'));
}

// The shadow methods the views show: a method's visibility itself, or the method a shown
// stage takes through a choice slot (composite.color shows composite.shadow's method, the
// error images error.method's).
std::vector<std::string> shownMethods(const UiState& state) {
  const Pipeline& pipeline = state.session.pipeline;
  const std::vector<std::string> methods = pipeline.methods();
  std::vector<std::string> shown;
  const auto add = [&](const std::string& stage) {
    if (std::find(methods.begin(), methods.end(), stage) != methods.end() &&
        std::find(shown.begin(), shown.end(), stage) == shown.end())
      shown.push_back(stage);
  };
  for (int v = 0; v < state.views.shownViews(); ++v) {
    const std::string& output = state.views.panels[v].output;
    if (output.empty() || !pipeline.hasStage(stageOf(output))) continue;
    const std::string stage = stageOf(output);
    if (std::find(methods.begin(), methods.end(), stage) != methods.end() && pipeline.methodOutput(stage) == output)
      add(stage);
    for (const Input& input : pipeline.stage(stage).inputs())
      if (input.isChoice() && (input.chooseRole & kRoleShadowMethod) && !(input.chooseRole & kRoleGroundTruth))
        if (const std::string source = pipeline.source(stage, input.name); !source.empty()) add(stageOf(source));
  }
  return shown;
}

// The ground truth's visibility ("reference.visibility"), "" if there is no comparison.
std::string truthOutputOf(const Pipeline& pipeline) {
  const Stage* truth = groundTruthStage(pipeline);
  if (!truth) return "";
  for (const Output& output : truth->outputs())
    if (output.roles & kRoleGroundTruth) return truth->name() + "." + output.name;
  return "";
}

void push(const TemporalPanelState& panel, std::deque<float>& values, float value) {
  values.push_back(value);
  while (int(values.size()) > panel.capacity) values.pop_front();
}

}  // namespace

void stepTemporalPanel(UiState& state) {
  TemporalPanelState& panel = state.panelMemory.temporal;
  Session& session = state.session;
  if (session.sceneLoads != panel.sceneLoads) {  // another scene: its own plot
    panel.sceneLoads = session.sceneLoads;
    clearPoints(panel);
  }
  if (!session.frame || !session.runError.empty()) return;
  // Monte Carlo's swimming: a new key (thesis Appendix A's) once per run, which the changed
  // run key then asks for. Only while playing, or on a static scene (no timeline).
  if (panel.perFrameKey && (session.playing || !session.animated()) &&
      panel.keyMovedAfterRun != session.pipelineRuns) {
    panel.keyMovedAfterRun = session.pipelineRuns;
    session.frame->frameKey += 1;
  }
  if (session.pipelineRuns == panel.lastRuns) return;
  panel.lastRuns = session.pipelineRuns;
  const Frame& frame = *session.frame;
  const Pipeline& pipeline = session.pipeline;
  const int w = frame.eyeWidth, h = frame.eyeHeight;
  if (w != panel.width || h != panel.height) {  // a new eye size (a preview, a resize): no pair
    panel.width = w, panel.height = h;
    panel.previousTruth.clear();
    for (auto& [method, series] : panel.series) series.previous.clear();
  }
  const size_t pixels = size_t(w) * size_t(h);
  // The ground truth and the counted pixels, where this run computed them.
  const std::string truthOutput = truthOutputOf(pipeline);
  const bool hasTruth = !truthOutput.empty() && ranLastRun(pipeline, truthOutput) && frame.has(truthOutput);
  std::vector<float> truth = hasTruth ? frame.texture(truthOutput).readFloats() : std::vector<float>(pixels, 0.0f);
  std::vector<std::uint8_t> counted;
  const std::string comparison = comparisonOutput(pipeline);
  if (!comparison.empty()) {
    const std::string mask = pipeline.source(stageOf(comparison), "mask");
    if (!mask.empty() && ranLastRun(pipeline, mask) && frame.has(mask))
      counted = countedPixels(frame.texture(mask).readFloats());
  }
  if (truth.size() != pixels || (!counted.empty() && counted.size() != pixels)) return;
  const bool pairWithTruth = hasTruth == panel.previousHadTruth && panel.previousTruth.size() == pixels;
  const std::vector<std::uint8_t> both =
      pairWithTruth ? bothCounted(panel.previousCounted.size() == pixels ? panel.previousCounted
                                                                        : std::vector<std::uint8_t>{},
                                  counted, pixels)
                    : std::vector<std::uint8_t>{};
  bool first = true;
  float truthChange = 0;
  for (const std::string& method : shownMethods(state)) {
    const std::string output = pipeline.methodOutput(method);
    if (method == stageOf(truthOutput) || !ranLastRun(pipeline, output) || !frame.has(output)) continue;
    TemporalPanelState::Series& series = panel.series[method];
    std::vector<float> visibility = frame.texture(output).readFloats();
    if (pairWithTruth && series.previous.size() == pixels && visibility.size() == pixels) {
      const TemporalChange change = temporalChange(series.previous, visibility, panel.previousTruth, truth, both);
      push(panel, series.change, float(change.change));
      push(panel, series.worstPixel, float(change.maxChange));
      truthChange = float(change.referenceChange);
      if (first) panel.last = change;
      first = false;
    }
    series.previous = std::move(visibility);
  }
  if (!first) push(panel, panel.truthChange, truthChange);
  panel.truthOutput = hasTruth ? truthOutput : "";
  panel.previousHadTruth = hasTruth;
  panel.previousTruth = std::move(truth);
  panel.previousCounted = std::move(counted);
}

void drawTemporalPanel(UiState& state) {
  TemporalPanelState& panel = state.panelMemory.temporal;
  ImGui::TextUnformatted("Temporal stability");
  helpMarker("Per run, the mean |visibility - visibility of the run before| of each shadow method "
             "the views show, over the pixels counted in both runs (receivers inside the light's "
             "map) whose ground truth did not change: change the truth does not explain. Monte "
             "Carlo noise swims when the frame key changes; a coarse map's texels crawl under a "
             "slowly moving occluder (thesis §4.1). Play the timeline to fill the plot. "
             "docs/decisions/120-temporal-stability.md; penumbra bench-temporal writes the same "
             "measure as a table.");
  ImGui::Checkbox("new frame key every run", &panel.perFrameKey);
  helpMarker("Adds 1 to the frame key (the hash key of thesis Appendix A) after every run while "
             "the timeline plays, or all the time on a static scene: Monte Carlo draws new light "
             "samples each frame and its noise shows as change. Off: the key stays as it is and "
             "a deterministic method on a still scene measures exactly 0.");
  ImGui::SetNextItemWidth(uiPixels(120));
  if (ImGui::SliderInt("frames kept", &panel.capacity, 10, 600)) {
    for (auto& [method, series] : panel.series)
      for (std::deque<float>* values : {&series.change, &series.worstPixel})
        while (int(values->size()) > panel.capacity) values->pop_front();
    while (int(panel.truthChange.size()) > panel.capacity) panel.truthChange.pop_front();
  }
  helpMarker("How many of the last measured pairs of runs the plot shows.");
  ImGui::SameLine();
  if (ImGui::Button("Clear")) clearPoints(panel);
  helpMarker("Forgets the plotted points (the next run starts a new pair).");
  if (panel.truthChange.empty())
    ImGui::TextWrapped("No pair of runs measured yet: play the timeline, or tick the key above.");
  else if (panel.truthOutput.empty())
    ImGui::TextWrapped("No ground truth this run (show the error view, with the reference or "
                       "raster4d): every counted pixel counts as stable, so real motion counts too.");
  else
    ImGui::TextWrapped("Ground truth: %s; stable pixels %zu of %zu counted", panel.truthOutput.c_str(),
                       panel.last.stable, panel.last.counted);

  // The plot: one line per method, the ground truth's own change in grey.
  float top = 1e-4f;
  size_t longest = panel.truthChange.size();
  for (const auto& [method, series] : panel.series) {
    for (float v : series.change) top = std::max(top, v);
    longest = std::max(longest, series.change.size());
  }
  for (float v : panel.truthChange) top = std::max(top, v);
  top *= 1.15f;  // headroom: the largest point below the frame's top
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = std::max(ImGui::GetContentRegionAvail().x, uiPixels(120)), height = uiPixels(140);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(origin, {origin.x + width, origin.y + height}, IM_COL32(25, 25, 30, 255));
  draw->AddRect(origin, {origin.x + width, origin.y + height}, IM_COL32(110, 110, 120, 255));
  const ImU32 colors[] = {IM_COL32(90, 170, 255, 255), IM_COL32(255, 150, 60, 255), IM_COL32(110, 220, 110, 255),
                          IM_COL32(240, 90, 200, 255), IM_COL32(240, 230, 80, 255), IM_COL32(160, 120, 255, 255)};
  const auto line = [&](const std::deque<float>& values, ImU32 color) {
    const int n = panel.capacity;
    for (size_t i = 1; i < values.size(); ++i) {
      const size_t offset = size_t(n) - values.size();  // newest at the right edge
      const auto at = [&](size_t k) {
        return ImVec2{origin.x + width * float(offset + k) / float(std::max(n - 1, 1)),
                      origin.y + height * (1 - values[k] / top)};
      };
      draw->AddLine(at(i - 1), at(i), color, 1.5f);
    }
  };
  line(panel.truthChange, IM_COL32(150, 150, 150, 255));
  int c = 0;
  for (const auto& [method, series] : panel.series) line(series.change, colors[c++ % 6]);
  char scale[64];
  std::snprintf(scale, sizeof scale, "%.4g", double(top));
  draw->AddText({origin.x + 3, origin.y + 2}, IM_COL32(200, 200, 200, 255), scale);
  draw->AddText({origin.x + 3, origin.y + height - ImGui::GetTextLineHeight() - 2}, IM_COL32(200, 200, 200, 255), "0");
  ImGui::Dummy({width, height});
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Mean |change| per run, the newest at the right; %d pairs at most; %zu shown.",
                      panel.capacity, longest);
  // The legend with the last and mean values.
  c = 0;
  for (const auto& [method, series] : panel.series) {
    double mean = 0, worst = 0;
    for (float v : series.change) mean += v, worst = std::max(worst, double(v));
    if (!series.change.empty()) mean /= double(series.change.size());
    const ImU32 color = colors[c++ % 6];
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(color), "%s", method.c_str());
    if (series.change.empty()) ImGui::TextUnformatted("  no pair yet");
    else ImGui::TextWrapped("  last %.5f  mean %.5f  worst %.5f", double(series.change.back()), mean, worst);
  }
  if (!panel.truthChange.empty()) {
    double mean = 0;
    for (float v : panel.truthChange) mean += v;
    mean /= double(panel.truthChange.size());
    ImGui::TextColored({0.6f, 0.6f, 0.6f, 1}, "truth's own change");
    helpMarker("The ground truth's mean |change| over every counted pixel: what really moved. "
               "The ratio of a method's change to it is in penumbra bench-temporal's table.");
    ImGui::TextWrapped("  last %.5f  mean %.5f", double(panel.truthChange.back()), mean);
  }
  if (panel.series.empty()) ImGui::TextWrapped("No shadow method shown: show a method's visibility "
                                               "or the final image in a view.");
}

bool temporalNumber(const UiState& state, const std::string& method, TemporalNumber kind, double& value,
                    std::string& problem) {
  const TemporalPanelState& panel = state.panelMemory.temporal;
  const bool pixel = kind == TemporalNumber::WorstPixel;
  const std::deque<float>* values = nullptr;
  if (method == "truth") {
    if (!pixel) values = &panel.truthChange;
  } else if (const auto series = panel.series.find(method); series != panel.series.end()) {
    values = pixel ? &series->second.worstPixel : &series->second.change;
  }
  if (!values || values->empty()) {
    problem = "no pair of runs measured for '" + method +
              "' (show the method in a view and run two poses or keys; {\"temporal_clear\": true} starts over)";
    return false;
  }
  double sum = 0, worst = 0;
  for (float v : *values) sum += v, worst = std::max(worst, double(v));
  const double mean = sum / double(values->size());
  if (kind == TemporalNumber::Mean) value = mean;
  else if (kind == TemporalNumber::WorstPixel) value = worst;
  else {  // the spread: standard deviation over the mean of the pairs' change
    if (values->size() < 2 || mean <= 0) {
      problem = "the spread of '" + method + "' needs two pairs with a change";
      return false;
    }
    double squares = 0;
    for (float v : *values) squares += (v - mean) * (v - mean);
    value = std::sqrt(squares / double(values->size() - 1)) / mean;
  }
  return true;
}

void clearTemporalPanel(UiState& state) { clearPoints(state.panelMemory.temporal); }
void setTemporalPerFrameKey(UiState& state, bool on) { state.panelMemory.temporal.perFrameKey = on; }

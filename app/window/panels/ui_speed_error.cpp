#include "window/panels/ui_speed_error.h"

#include <imgui.h>

#include "bench/plot.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>

#include "bench/bench_json.h"
#include "bench/live_bench.h"
#include "bench/pareto.h"
#include "core/pipeline.h"
#include "window/ui_state.h"
#include "window/ui_widgets.h"

std::string newestBenchJson(const std::filesystem::path& directory) {
  namespace fs = std::filesystem;
  std::error_code error;
  fs::path newest;
  fs::file_time_type newestTime{};
  for (const auto& entry : fs::directory_iterator(directory / "bench", error)) {
    const fs::path json = entry.path() / "results.json";
    if (!fs::is_regular_file(json, error)) continue;
    const auto time = fs::last_write_time(json, error);
    if (newest.empty() || time > newestTime) newest = json, newestTime = time;
  }
  return newest.empty() ? "" : fs::relative(newest, directory, error).string();
}

ChartLayout speedErrorChartLayout(const std::vector<const BenchResult*>& points) {
  std::vector<double> xs, ys;
  for (const BenchResult* p : points) xs.push_back(p->msMedian), ys.push_back(p->error.meanAbsInShadow);
  return chartLayout(xs, ys, paretoFrontier(xs, ys), /*logX=*/true, /*logY=*/true);
}

namespace {

// 1. The panel's state (UiState::speedError, window/ui_state_speed_error.h): the live run,
//    or a loaded file.
using PanelState = SpeedErrorPanelState;

void load(PanelState& panel) {
  panel.loadedPath = panel.path;
  panel.fileResults.clear();
  panel.fileSetups.clear();
  panel.fileSetup = 0;
  std::ifstream file(panel.path);
  if (!file) {
    panel.fileMessage = panel.loadedPath.empty() ? "no results.json given" : "cannot read " + panel.loadedPath;
    return;
  }
  std::stringstream text;
  text << file.rdbuf();
  panel.fileMessage = parseBenchJson(text.str(), panel.fileInfo, panel.fileSetups, panel.fileResults);
}

// Colour and shape per series (bench/plot.h, as the report's charts), in the order the
// series first appear; the window's plot is dark, so black is drawn white.
ImU32 seriesColour(size_t index) {
  const SeriesStyle style = seriesStyle(int(index));
  if (style.r + style.g + style.b == 0) return IM_COL32(235, 235, 235, 255);
  return IM_COL32(int(style.r * 255), int(style.g * 255), int(style.b * 255), 255);
}

void seriesMarker(ImDrawList* draw, ImVec2 p, size_t index, float r) {
  const ImU32 colour = seriesColour(index);
  const MarkerOutline outline = markerOutline(seriesStyle(int(index)).shape);  // as the report's
  if (outline.circle) {
    draw->AddCircleFilled(p, float(outline.radius) * r, colour);
    return;
  }
  std::vector<ImVec2> points;
  for (const auto& v : outline.vertices) points.push_back({p.x + float(v[0]) * r, p.y + float(v[1]) * r});
  draw->AddConvexPolyFilled(points.data(), int(points.size()), colour);
}

// 2. The chart: points (only those measured: frames > 0), frontier, the current one ringed.
void drawPlot(const std::vector<const BenchResult*>& points, int current) {
  const float em = ImGui::GetFontSize();  // margins follow the UI scale
  // The axis titles are text lines above and below the plot: inside it they ran past its
  // right edge in a narrow panel (at UI scale 1.5, "mean |error| in sha").
  ImGui::TextWrapped("y: mean |error| in shadow (log)");
  const ImVec2 size{ImGui::GetContentRegionAvail().x, 18 * em};
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("##plot", size);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float left = origin.x + 3.7f * em, right = origin.x + size.x - 0.6f * em;
  const float top = origin.y + 0.5f * em, bottom = origin.y + size.y - 1.4f * em;
  draw->AddRectFilled({left, top}, {right, bottom}, IM_COL32(30, 30, 34, 255));
  draw->AddRect({left, top}, {right, bottom}, IM_COL32(120, 120, 120, 255));
  // The chart's layout (bench/plot_layout.h), as the report's charts: log ranges, ticks, the
  // frontier in increasing time; mapped here onto the panel's box.
  const ChartLayout chart = speedErrorChartLayout(points);
  auto at = [&](const BenchResult& p) {
    return ImVec2{left + float(chart.x.at(p.msMedian)) * (right - left),
                  bottom - float(chart.y.at(p.error.meanAbsInShadow)) * (bottom - top)};
  };
  // A label centred on its line, left out where it would touch the one before it or leave
  // the plot's box (they ran together at UI scale 1.5).
  const ImU32 grid = IM_COL32(70, 70, 76, 255), label = IM_COL32(180, 180, 180, 255);
  float labelEnd = -INFINITY;
  for (double v : chart.x.ticks) {
    const float x = left + float(chart.x.at(v)) * (right - left);
    draw->AddLine({x, top}, {x, bottom}, grid);
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    const float width = ImGui::CalcTextSize(text).x, start = x - 0.5f * width;
    if (start < labelEnd + 0.5f * em || start + width > origin.x + size.x) continue;
    draw->AddText({start, bottom + 2}, label, text);
    labelEnd = start + width;
  }
  for (double v : chart.y.ticks) {
    const float y = bottom - float(chart.y.at(v)) * (bottom - top);
    draw->AddLine({left, y}, {right, y}, grid);
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    draw->AddText({origin.x, y - 0.5f * em}, label, text);
  }
  // Frontier (increasing time), points coloured by method, the current configuration.
  std::vector<bool> onFrontier(points.size(), false);
  for (size_t i : chart.frontier) onFrontier[i] = true;
  for (size_t i = 1; i < chart.frontier.size(); ++i)
    draw->AddLine(at(*points[chart.frontier[i - 1]]), at(*points[chart.frontier[i]]), IM_COL32(255, 190, 60, 255), 2);
  std::vector<std::string> methods;
  int hovered = -1;
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  for (size_t i : chart.drawable) {
    const std::string legend = seriesLegend(points[i]->method, points[i]->family);
    auto it = std::find(methods.begin(), methods.end(), legend);
    if (it == methods.end()) methods.push_back(legend), it = methods.end() - 1;
    const ImVec2 p = at(*points[i]);
    seriesMarker(draw, p, size_t(it - methods.begin()), 0.3f * em);
    if (onFrontier[i]) draw->AddCircle(p, 5.5f, IM_COL32(255, 190, 60, 255));
    if (std::hypot(mouse.x - p.x, mouse.y - p.y) < 6) hovered = int(i);
  }
  if (current >= 0) draw->AddCircle(at(*points[size_t(current)]), 8, IM_COL32(80, 255, 120, 255), 0, 2.5f);
  if (hovered >= 0 && ImGui::IsItemHovered()) {
    const BenchResult& p = *points[size_t(hovered)];
    std::string stages;
    for (const std::string& stage : p.stages) stages += (stages.empty() ? "" : " + ") + stage;
    ImGui::SetTooltip("%s\n%.2f ms/frame (%s), mean |error| in shadow %.4f", p.label.c_str(),
                      p.msMedian, stages.c_str(), p.error.meanAbsInShadow);
  }
  ImGui::TextWrapped("x: ms per frame (median, log)");
  // The legend wraps in a narrow panel: entries are placed by their measured widths.
  const float lineWidth = ImGui::GetContentRegionAvail().x, gap = ImGui::GetStyle().ItemSpacing.x;
  float used = ImGui::CalcTextSize("-- Pareto frontier").x;
  ImGui::TextColored({1, 0.75f, 0.25f, 1}, "-- Pareto frontier");
  const float markerWidth = 1.2f * em;
  for (size_t m = 0; m < methods.size(); ++m) {
    const float width = markerWidth + ImGui::CalcTextSize(methods[m].c_str()).x;
    if (used + gap + width <= lineWidth) {
      ImGui::SameLine();
      used += gap + width;
    } else
      used = width;
    // The entry's own marker, then its name: shape and colour as on the chart.
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::Dummy({markerWidth, ImGui::GetTextLineHeight()});
    seriesMarker(ImGui::GetWindowDrawList(), {at.x + 0.5f * markerWidth, at.y + 0.5f * ImGui::GetTextLineHeight()},
                 m, 0.3f * em);
    ImGui::SameLine(0, 0);
    // An entry wider than the panel (a long configuration at a large UI scale) wraps at its
    // spaces instead of running past the edge.
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::ColorConvertU32ToFloat4(seriesColour(m)));
    if (width > lineWidth) ImGui::TextWrapped("%s", methods[m].c_str());
    else ImGui::TextUnformatted(methods[m].c_str());
    ImGui::PopStyleColor();
  }
}

// The presets a live run can measure: every one but `animated`, whose frames are a whole
// cycle of poses (`penumbra bench --preset animated`); the live run measures the view shown,
// at the timeline's time.
std::vector<std::string> livePresets() {
  std::vector<std::string> presets = benchPresetNames();
  presets.erase(std::remove(presets.begin(), presets.end(), "animated"), presets.end());
  return presets;
}

// 3. The live run's controls: preset, measure / cancel, progress.
std::string startRun(PanelState& panel, const UiState& state, const std::string& preset) {
  try {
    LiveBenchOptions options;
    options.preset = preset;
    panel.bench.start(state.session.scene, state.session.pipeline, options);
    return "";
  } catch (const std::exception& error) {
    return error.what();
  }
}

void drawLiveControls(PanelState& panel, UiState& state) {
  const std::vector<std::string> presets = livePresets();
  ImGui::SetNextItemWidth(10 * ImGui::GetFontSize());
  if (ImGui::BeginCombo("preset", presets[size_t(panel.preset)].c_str())) {
    for (size_t i = 0; i < presets.size(); ++i)
      if (ImGui::Selectable(presets[i].c_str(), int(i) == panel.preset)) panel.preset = int(i);
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("The configurations measured: the preset's first setup (as `penumbra "
                      "bench --preset`), plus the window's current parameters. Every preset has "
                      "the reference as a method at 1x1 to 8x8 samples. A whole animation loop: "
                      "`penumbra bench --preset animated`.");
  if (panel.bench.running()) {
    if (ImGui::Button("Cancel")) panel.bench.cancel();
  } else if (ImGui::Button("Measure this scene")) {
    panel.liveMessage = startRun(panel, state, presets[size_t(panel.preset)]);
  }
  if (panel.bench.running()) {
    ImGui::ProgressBar(panel.bench.progress(), {-1, 0});
    ImGui::TextWrapped("%s", panel.bench.status().c_str());
  }
  if (!panel.liveMessage.empty()) ImGui::TextColored({1, 0.5f, 0.4f, 1}, "%s", panel.liveMessage.c_str());
}

PanelState& panelState(UiState& state) {
  PanelState& panel = state.speedError;
  if (!panel.initialised) {
    panel.initialised = true;
    const std::string newest = newestBenchJson(std::filesystem::current_path());
    std::snprintf(panel.path, sizeof panel.path, "%s", newest.c_str());
  }
  return panel;
}

}  // namespace

std::string startSpeedErrorRun(UiState& state, const std::string& preset) {
  PanelState& panel = panelState(state);
  const std::vector<std::string> presets = livePresets();
  const auto found = std::find(presets.begin(), presets.end(), preset);
  if (found == presets.end()) {
    std::string valid;
    for (const std::string& name : presets) valid += (valid.empty() ? "" : ", ") + name;
    return "unknown preset '" + preset + "'; valid: " + valid;
  }
  if (panel.bench.running()) return "a live run is already measuring";
  panel.preset = int(found - presets.begin());
  panel.live = true;
  panel.liveMessage = startRun(panel, state, preset);
  return panel.liveMessage;
}

bool speedErrorRunning(const UiState& state) { return state.speedError.bench.running(); }

int speedErrorPoints(const UiState& state) {
  const std::vector<BenchResult>& results = state.speedError.bench.results();
  return int(std::count_if(results.begin(), results.end(), [](const BenchResult& r) { return r.frames > 0; }));
}

void stepSpeedErrorPanel(UiState& state) {
  PanelState& panel = state.speedError;
  if (!panel.bench.running()) return;
  try {
    panel.bench.step();
  } catch (const std::exception& error) {
    panel.liveMessage = error.what();
    panel.bench.cancel();
  }
}

void drawSpeedErrorPanel(UiState& state) {
  PanelState& panel = panelState(state);
  if (ImGui::RadioButton("live: this scene", panel.live)) panel.live = true;
  sameLineIfButtonsFit({"(o) a results.json"});
  if (ImGui::RadioButton("a results.json", !panel.live)) {
    panel.live = false;
    if (panel.loadedPath.empty()) load(panel);
  }

  std::vector<const BenchResult*> points;
  int current = -1;
  if (panel.live) {
    drawLiveControls(panel, state);
    for (const BenchResult& r : panel.bench.results())
      if (r.frames > 0) points.push_back(&r);
    if (!points.empty()) {
      const bool sameScene = panel.bench.fingerprint() == sceneFingerprint(state.session.scene);
      std::vector<BenchResult> measured;
      for (const BenchResult* r : points) measured.push_back(*r);
      if (sameScene) current = matchingResult(measured, state.session.pipeline);
      ImGui::TextWrapped("%s%s", panel.bench.setupLabel().c_str(),
                         sameScene ? "" : " (the scene, light or camera changed since: no point is current)");
      ImGui::TextWrapped("truth: Embree %dx%d stratified", panel.bench.referenceSamples(),
                         panel.bench.referenceSamples());
      // A tooltip on the line itself: a (?) after a wrapped line would run past the panel.
      if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
        ImGui::TextUnformatted("Every error is measured against the exact reference at this many "
                               "light samples per pixel. The reference is also a method here "
                               "(\"reference (Embree, CPU)\", 1x1 to 8x8 samples at the cell "
                               "centres): where its points lie left of or below another method's, "
                               "the CPU ray tracer is the better choice on this machine.");
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
      }
    }
  } else {
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 60);
    const bool entered = ImGui::InputText("##json", panel.path, sizeof panel.path,
                                          ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("Load") || entered) load(panel);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("A results.json written by `penumbra bench --out DIR`.");
    if (!panel.fileMessage.empty()) ImGui::TextColored({1, 0.5f, 0.4f, 1}, "%s", panel.fileMessage.c_str());
    if (panel.fileSetups.size() > 1) {
      ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x);
      if (ImGui::BeginCombo("##setup", panel.fileSetups[size_t(panel.fileSetup)].label.c_str())) {
        for (size_t i = 0; i < panel.fileSetups.size(); ++i)
          if (ImGui::Selectable(panel.fileSetups[i].label.c_str(), int(i) == panel.fileSetup))
            panel.fileSetup = int(i);
        ImGui::EndCombo();
      }
    }
    for (const BenchResult& r : panel.fileResults)  // the frontier is per setup
      if (r.setup == size_t(panel.fileSetup)) points.push_back(&r);
    if (!points.empty())
      ImGui::TextWrapped("%s, %s (another run: no point is marked current); truth: Embree %dx%d",
                         panel.fileInfo.scene.c_str(), panel.fileInfo.started.c_str(),
                         panel.fileInfo.referenceSamples, panel.fileInfo.referenceSamples);
  }
  if (!points.empty()) {
    drawPlot(points, current);
    if (current >= 0) {
      ImGui::TextColored({0.3f, 1, 0.5f, 1}, "(O) current:");
      ImGui::TextWrapped("%s", points[size_t(current)]->label.c_str());
      ImGui::Text("%.2f ms, error %.4f", points[size_t(current)]->msMedian,  // unwrapped: a
                  points[size_t(current)]->error.meanAbsInShadow);  // wrap split "0.|0221"
    } else if (panel.live)
      ImGui::TextWrapped("The current parameters were not measured in this run on this view "
                         "(measure again to add them).");
  }
}

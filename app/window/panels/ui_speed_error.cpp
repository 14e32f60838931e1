#include "window/panels/ui_speed_error.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "core/pipeline.h"
#include "window/ui_state.h"

namespace {

// 1. CSV: fields may be quoted ("" inside quotes is a quote), as bench_output.cpp writes them.
std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') fields.back() += '"', ++i;
    else if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) fields.emplace_back();
    else if (c != '\r') fields.back() += c;
  }
  return fields;
}

}  // namespace

std::string parseSpeedErrorCsv(const std::string& text, std::vector<SpeedErrorPoint>& points) {
  points.clear();
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line)) return "empty file";
  std::map<std::string, size_t> column;
  const std::vector<std::string> header = splitCsvLine(line);
  for (size_t i = 0; i < header.size(); ++i) column[header[i]] = i;
  for (const char* name : {"setup", "config", "method", "search", "layers", "rays_per_side",
                           "shadow_map", "deferred", "filter", "ms_median",
                           "mean_abs_error_in_shadow"})
    if (!column.count(name)) return std::string("no column ") + name + " (not a bench results.csv?)";
  int row = 1;
  while (std::getline(in, line)) {
    ++row;
    if (line.empty()) continue;
    const std::vector<std::string> f = splitCsvLine(line);
    if (f.size() != header.size()) return "row " + std::to_string(row) + ": wrong field count";
    auto get = [&](const char* name) { return f[column[name]]; };
    auto number = [&](const char* name) { return get(name).empty() ? 0.0 : std::stod(get(name)); };
    SpeedErrorPoint p;
    try {
      p.setup = get("setup");
      p.config = get("config");
      p.method = get("method");
      p.search = get("search");
      p.layers = get("layers");
      p.rays = int(number("rays_per_side"));
      p.shadowMap = int(number("shadow_map"));
      p.deferred = get("deferred") == "1";
      p.filter = get("filter") == "1";
      p.msMedian = number("ms_median");
      p.meanAbsErrorInShadow = number("mean_abs_error_in_shadow");
    } catch (const std::exception&) {
      return "row " + std::to_string(row) + ": not a number";
    }
    points.push_back(p);
  }
  return "";
}

std::vector<size_t> paretoFrontier(const std::vector<SpeedErrorPoint>& points) {
  std::vector<size_t> order(points.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    if (points[a].msMedian != points[b].msMedian) return points[a].msMedian < points[b].msMedian;
    return points[a].meanAbsErrorInShadow < points[b].meanAbsErrorInShadow;
  });
  // Sweep by increasing time: a point is on the frontier if it is more accurate than every
  // faster point.
  std::vector<size_t> frontier;
  double bestError = INFINITY;
  for (size_t i : order)
    if (points[i].meanAbsErrorInShadow < bestError) {
      frontier.push_back(i);
      bestError = points[i].meanAbsErrorInShadow;
    }
  return frontier;
}

int matchingPoint(const std::vector<SpeedErrorPoint>& points, const PipelineConfig& c) {
  for (size_t i = 0; i < points.size(); ++i) {
    const SpeedErrorPoint& p = points[i];
    if (p.method == "monte_carlo" && p.search == c.search && p.layers == c.layers &&
        p.rays == c.rays && p.shadowMap == c.shadowMap && p.deferred == c.deferred &&
        p.filter == c.filter)
      return int(i);
  }
  return -1;
}

PipelineConfig pipelineConfigOf(const Pipeline& pipeline) {
  PipelineConfig c;
  c.search = pipeline.param("trace.search").asEnum();
  c.layers = pipeline.param("light.layers").asEnum();
  c.rays = int(pipeline.param("trace.rays").value);
  c.shadowMap = int(pipeline.param("light.resolution").value);
  c.deferred = pipeline.param("trace.deferred").value != 0;
  c.filter = pipeline.param("filter.enabled").value != 0;
  return c;
}

std::string newestBenchCsv(const std::filesystem::path& directory) {
  namespace fs = std::filesystem;
  std::error_code error;
  fs::path newest;
  fs::file_time_type newestTime{};
  for (const auto& entry : fs::directory_iterator(directory / "bench", error)) {
    const fs::path csv = entry.path() / "results.csv";
    if (!fs::is_regular_file(csv, error)) continue;
    const auto time = fs::last_write_time(csv, error);
    if (newest.empty() || time > newestTime) newest = csv, newestTime = time;
  }
  return newest.empty() ? "" : fs::relative(newest, directory, error).string();
}

// 2. The panel.
namespace {

struct PanelState {
  bool initialised = false;
  char path[512] = "";
  std::string loadedPath, message;
  std::vector<SpeedErrorPoint> all;
  std::vector<std::string> setups;
  int setup = 0;
};

void load(PanelState& panel) {
  panel.loadedPath = panel.path;
  panel.all.clear();
  panel.setups.clear();
  panel.setup = 0;
  std::ifstream file(panel.path);
  if (!file) {
    panel.message = panel.loadedPath.empty() ? "no results.csv given" : "cannot read " + panel.loadedPath;
    return;
  }
  std::stringstream text;
  text << file.rdbuf();
  panel.message = parseSpeedErrorCsv(text.str(), panel.all);
  for (const SpeedErrorPoint& p : panel.all)
    if (std::find(panel.setups.begin(), panel.setups.end(), p.setup) == panel.setups.end())
      panel.setups.push_back(p.setup);
}

// Log-scale axes over the points, one decade at least.
struct LogAxis {
  double lo, hi;
  float to(double v, float a, float b) const {
    const double t = (std::log10(std::max(v, 1e-9)) - lo) / (hi - lo);
    return a + float(t) * (b - a);
  }
};

LogAxis axisFor(const std::vector<double>& values) {
  double lo = INFINITY, hi = -INFINITY;
  for (double v : values)
    if (v > 0) lo = std::min(lo, std::log10(v)), hi = std::max(hi, std::log10(v));
  if (!std::isfinite(lo)) return {-1, 0};
  lo = std::floor(lo * 5) / 5 - 0.1;
  hi = std::ceil(hi * 5) / 5 + 0.1;
  return {lo, std::max(hi, lo + 0.5)};
}

void drawPlot(const std::vector<SpeedErrorPoint>& points, int match) {
  const ImVec2 size{ImGui::GetContentRegionAvail().x, 260};
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("##plot", size);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float left = origin.x + 48, right = origin.x + size.x - 8;
  const float top = origin.y + 6, bottom = origin.y + size.y - 34;
  draw->AddRectFilled({left, top}, {right, bottom}, IM_COL32(30, 30, 34, 255));
  draw->AddRect({left, top}, {right, bottom}, IM_COL32(120, 120, 120, 255));
  std::vector<double> xs, ys;
  for (const SpeedErrorPoint& p : points) xs.push_back(p.msMedian), ys.push_back(p.meanAbsErrorInShadow);
  const LogAxis ax = axisFor(xs), ay = axisFor(ys);
  auto at = [&](const SpeedErrorPoint& p) {
    return ImVec2{ax.to(p.msMedian, left, right), ay.to(p.meanAbsErrorInShadow, bottom, top)};
  };
  // Decade and 2x / 5x ticks with labels.
  const ImU32 grid = IM_COL32(70, 70, 76, 255), label = IM_COL32(180, 180, 180, 255);
  for (int decade = int(std::floor(ax.lo)); decade <= int(std::ceil(ax.hi)); ++decade)
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, decade);
      if (std::log10(v) < ax.lo || std::log10(v) > ax.hi) continue;
      const float x = ax.to(v, left, right);
      draw->AddLine({x, top}, {x, bottom}, grid);
      char text[32];
      std::snprintf(text, sizeof text, "%g", v);
      draw->AddText({x - 8, bottom + 2}, label, text);
    }
  for (int decade = int(std::floor(ay.lo)); decade <= int(std::ceil(ay.hi)); ++decade)
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, decade);
      if (std::log10(v) < ay.lo || std::log10(v) > ay.hi) continue;
      const float y = ay.to(v, bottom, top);
      draw->AddLine({left, y}, {right, y}, grid);
      char text[32];
      std::snprintf(text, sizeof text, "%g", v);
      draw->AddText({origin.x, y - 7}, label, text);
    }
  draw->AddText({left + 60, bottom + 17}, label, "ms per frame (median, log)");
  draw->AddText({left + 4, top + 2}, label, "mean |error| in shadow (log)");
  // Frontier, points, the current configuration.
  const std::vector<size_t> frontier = paretoFrontier(points);
  for (size_t i = 1; i < frontier.size(); ++i)
    draw->AddLine(at(points[frontier[i - 1]]), at(points[frontier[i]]), IM_COL32(255, 190, 60, 255), 2);
  int hovered = -1;
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  for (size_t i = 0; i < points.size(); ++i) {
    const ImVec2 p = at(points[i]);
    const bool onFrontier = std::find(frontier.begin(), frontier.end(), i) != frontier.end();
    const ImU32 colour = points[i].method == "hard_shadow" ? IM_COL32(230, 90, 90, 255)
                         : onFrontier                       ? IM_COL32(255, 190, 60, 255)
                                                            : IM_COL32(110, 170, 255, 255);
    draw->AddCircleFilled(p, 3.5f, colour);
    if (std::hypot(mouse.x - p.x, mouse.y - p.y) < 6) hovered = int(i);
  }
  if (match >= 0) {
    const ImVec2 p = at(points[size_t(match)]);
    draw->AddCircle(p, 8, IM_COL32(80, 255, 120, 255), 0, 2.5f);
  }
  if (hovered >= 0 && ImGui::IsItemHovered()) {
    const SpeedErrorPoint& p = points[size_t(hovered)];
    ImGui::SetTooltip("%s\n%.2f ms/frame, mean |error| in shadow %.4f", p.config.c_str(),
                      p.msMedian, p.meanAbsErrorInShadow);
  }
}

}  // namespace

void drawSpeedErrorPanel(UiState& state, float x, float y, float width) {
  static PanelState panel;
  if (!panel.initialised) {
    panel.initialised = true;
    const std::string newest = newestBenchCsv(std::filesystem::current_path());
    std::snprintf(panel.path, sizeof panel.path, "%s", newest.c_str());
    load(panel);
  }
  ImGui::SetNextWindowPos({x, y}, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize({width, 0}, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Speed vs error (penumbra bench)", nullptr, 0)) {
    ImGui::End();
    return;
  }
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 60);
  const bool entered = ImGui::InputText("##csv", panel.path, sizeof panel.path,
                                        ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if (ImGui::Button("Load") || entered) load(panel);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("A results.csv written by `penumbra bench --out DIR`.");
  if (!panel.message.empty()) ImGui::TextColored({1, 0.5f, 0.4f, 1}, "%s", panel.message.c_str());
  if (panel.setups.size() > 1) {
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x);
    if (ImGui::BeginCombo("##setup", panel.setups[size_t(panel.setup)].c_str())) {
      for (size_t i = 0; i < panel.setups.size(); ++i)
        if (ImGui::Selectable(panel.setups[i].c_str(), int(i) == panel.setup)) panel.setup = int(i);
      ImGui::EndCombo();
    }
  }
  std::vector<SpeedErrorPoint> points;  // the chosen setup: the frontier is per setup
  for (const SpeedErrorPoint& p : panel.all)
    if (!panel.setups.empty() && p.setup == panel.setups[size_t(panel.setup)]) points.push_back(p);
  if (!points.empty()) {
    int match = -1;
    std::string current = "?";
    try {
      const PipelineConfig config = pipelineConfigOf(state.session.pipeline);
      match = matchingPoint(points, config);
      char text[160];
      std::snprintf(text, sizeof text, "%s %s layers %dx%d map %d%s%s", config.search.c_str(),
                    config.layers.c_str(), config.rays, config.rays, config.shadowMap,
                    config.deferred ? "" : " forward", config.filter ? "" : " unfiltered");
      current = text;
    } catch (const std::exception& error) {
      current = error.what();
    }
    drawPlot(points, match);
    ImGui::TextColored({1, 0.75f, 0.25f, 1}, "-- Pareto frontier");
    ImGui::SameLine();
    ImGui::TextColored({0.4f, 0.67f, 1, 1}, "o Monte Carlo");
    ImGui::SameLine();
    ImGui::TextColored({0.9f, 0.35f, 0.35f, 1}, "o hard shadow");
    if (match >= 0)
      ImGui::TextColored({0.3f, 1, 0.5f, 1}, "(O) current: %s, %.2f ms, error %.4f",
                         points[size_t(match)].config.c_str(), points[size_t(match)].msMedian,
                         points[size_t(match)].meanAbsErrorInShadow);
    else
      ImGui::TextWrapped("current (%s): no exact match in this report", current.c_str());
  }
  ImGui::End();
}

// The "speed vs error" panel (issue 5): the points of a `penumbra bench` results.csv
// (app/bench/bench_output.cpp's columns), time against mean |error| in shadow on log axes, the
// Pareto frontier, and the configuration matching the current pipeline parameters.
// Parsing, the frontier and the match are pure functions (tests/window/test_window_speed_error.cpp).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

class Pipeline;
class UiState;

// One row of results.csv: what the panel needs.
struct SpeedErrorPoint {
  std::string setup, config, method, search, layers;
  int rays = 0, shadowMap = 0;
  bool deferred = false, filter = false;
  double msMedian = 0, meanAbsErrorInShadow = 0;
};

// Parses results.csv text by its header's column names; "" or the problem.
std::string parseSpeedErrorCsv(const std::string& text, std::vector<SpeedErrorPoint>& points);
// Indices of the points no other point beats on both time and error, by increasing time.
std::vector<size_t> paretoFrontier(const std::vector<SpeedErrorPoint>& points);
// The point whose configuration equals the given parameters; -1 if none. search is the
// trace.search option name, layers the light.layers option name ("one".."three").
struct PipelineConfig {
  std::string search, layers;
  int rays = 0, shadowMap = 0;
  bool deferred = false, filter = false;
};
int matchingPoint(const std::vector<SpeedErrorPoint>& points, const PipelineConfig& config);
PipelineConfig pipelineConfigOf(const Pipeline& pipeline);  // throws if a key is missing
// The newest bench/*/results.csv under `directory`; "" if none.
std::string newestBenchCsv(const std::filesystem::path& directory);

// The floating panel (starts collapsed).
void drawSpeedErrorPanel(UiState& state, float x, float y, float width);

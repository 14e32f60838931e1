// The "speed vs error" panel (docs/design.md#bench): time against mean |error| in
// shadow on log axes with the Pareto frontier (app/bench/pareto.h), for
//  - a live run (app/bench/live_bench.h): the current scene's methods and configurations
//    measured in the background, one step per window frame, with progress and cancel; the
//    window's own parameters are one of the configurations. A point is marked "current" only
//    when it comes from this run, the scene (geometry, light, camera) is still the one
//    measured, and its method and parameters equal the pipeline's now. The reference is one
//    of the methods (bench/bench_reference.h: Embree at 1x1 .. 8x8 light samples, measured
//    against the run's 16x16 truth), so the chart shows when a CPU ray tracer is the better
//    choice on this machine;
//  - or a `penumbra bench` results.json (never marked current: another run).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "bench/bench_report.h"
#include "bench/plot_layout.h"

class UiState;

// The chart's layout (bench/plot_layout.h, the report's charts' too) of these measured
// points: time (msMedian) against mean |error| in shadow, both log, the Pareto frontier.
ChartLayout speedErrorChartLayout(const std::vector<const BenchResult*>& points);

// The newest bench/*/results.json under `directory`, relative to it; "" if none.
std::string newestBenchJson(const std::filesystem::path& directory);

// As the "Measure this scene" button with `preset` chosen (scripts: "speed_error_measure");
// "" or why not (an unknown preset, a run already going, a bad parameter).
std::string startSpeedErrorRun(UiState& state, const std::string& preset);
bool speedErrorRunning(const UiState& state);
int speedErrorPoints(const UiState& state);  // configurations the live run has measured
// One step of the live run; called every window frame, whether the panel is shown or not.
void stepSpeedErrorPanel(UiState& state);
// The panel's contents, drawn into the current window (the right side panel's "Speed vs
// error" tab: a fixed region that never covers the views or catches their drags).
void drawSpeedErrorPanel(UiState& state);

// The files `penumbra bench` writes: results.json (everything, app/bench/bench_json.h),
// results.csv (one row per configuration, fixed columns), results.md (tables a report can
// include, with the machine, the method and the stages each method's time covers) and the
// charts speed_vs_error* / error_vs_* as PNG, SVG and PDF (app/bench/plot.h).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "bench/bench_configs.h"
#include "bench/bench_json.h"
#include "bench/bench_report.h"

std::vector<std::string> benchCsvColumns();

// Marks each result's `pareto` flag (per setup; minimising ms and mean |error| in shadow).
void markParetoFrontiers(std::vector<BenchResult>& results);

// Writes every file; returns their paths.
std::vector<std::filesystem::path> writeBenchOutputs(const std::filesystem::path& directory,
                                                     const BenchRunInfo& info,
                                                     const std::vector<BenchSetup>& setups,
                                                     const std::vector<BenchResult>& results);

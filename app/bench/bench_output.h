// The files `penumbra bench` writes: results.csv (one row per configuration, fixed
// columns), results.md (tables a report can include, with the machine and method), and
// speed_vs_error*.png / error_vs_*.png (app/bench/plot_png.h).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "bench/bench_configs.h"
#include "bench/bench_report.h"

struct BenchRunInfo {
  std::string scene, preset, commandLine, renderer, cpu, started;
  std::string loadBefore, loadAfter;  // /proc/loadavg: the cores are shared
  int frames = 0, warmup = 0, rounds = 1, referenceSamples = 0;
  double seconds = 0;
};

std::vector<std::string> benchCsvColumns();

// Marks each result's `pareto` flag (per setup; minimising ms and mean |error| in shadow).
void markParetoFrontiers(std::vector<BenchResult>& results);

// Writes every file; returns their paths.
std::vector<std::filesystem::path> writeBenchOutputs(const std::filesystem::path& directory,
                                                     const BenchRunInfo& info,
                                                     const std::vector<BenchSetup>& setups,
                                                     const std::vector<BenchResult>& results);

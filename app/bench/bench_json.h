// results.json: everything `penumbra bench` measured (app/bench/bench_report.h), written with
// nlohmann::json and read back by the window's speed-against-error panel.
#pragma once
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

// A setup as the report needs it (no scene geometry).
struct BenchSetupInfo {
  std::string label, axis;
  double axisValue = 0;
  int width = 0, height = 0;
  // An animated setup (preset animated): frames per second, one cycle's seconds, and the
  // milliseconds of posing + uploading each frame; empty / 0 otherwise.
  double fps = 0, cycle = 0;
  std::vector<double> loopTimes, poseMs;
};
std::vector<BenchSetupInfo> setupInfos(const std::vector<BenchSetup>& setups);

std::string benchJson(const BenchRunInfo& info, const std::vector<BenchSetupInfo>& setups,
                      const std::vector<BenchResult>& results);
// Parses results.json text; "" or the problem (not JSON, a missing field, ...).
std::string parseBenchJson(const std::string& text, BenchRunInfo& info,
                           std::vector<BenchSetupInfo>& setups, std::vector<BenchResult>& results);

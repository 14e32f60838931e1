// `penumbra bench-stages`: per-stage milliseconds (median of N frames after warm-up,
// glFinish + steady clock), texel fetches per ray for each search mode and the share of
// receiver pixels that classification spares, on `cube` and `engine` (thesis Tables 4.1-4.2
// shapes). A benchmark program: it writes numbers, asserts nothing.
#pragma once
#include <string>
#include <vector>

struct BenchStagesOptions {
  std::string out = "bench/stages.md";
  int frames = 12, warmup = 2;
  int width = 512, height = 512, mapSize = 512;
  std::string scenes = "cube,engine";
  std::vector<std::string> sets;  // applied to every configuration

};

int runBenchStages(const BenchStagesOptions& options);

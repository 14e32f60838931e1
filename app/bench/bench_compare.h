// `penumbra bench-compare` (docs/design.md#bench): configurations of one scene timed back to back
// in one run, frames alternating between them, so ratios hold on a loaded machine: per stage the
// median milliseconds, the whole run's, chosen counters per frame, and (optionally) the error
// against the Embree reference. A benchmark program: it writes numbers, asserts nothing.
#pragma once
#include <string>
#include <vector>

struct BenchCompareOptions {
  std::string out = "bench/compare.md";
  std::string scene = "cube";
  int frames = 6, warmup = 1;
  int width = 640, height = 480;
  std::vector<std::string> sets;   // for every side
  std::vector<std::string> sides;  // "label:stage.key=value;stage.key=value"
  std::vector<std::string> requested;  // outputs to run for (empty: everything)
  std::vector<std::string> counters;   // frame counters to report ("trace.fetches", ...)
  std::string errorOf;  // a method ("filter", "trace"): its error against the reference
  std::string title;
};

int runBenchCompare(const BenchCompareOptions& options);

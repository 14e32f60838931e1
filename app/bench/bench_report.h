// `penumbra bench`: speed against error (DESIGN.md §7). For each setup of the plan
// (app/bench/bench_configs.h) the exact reference is computed once (stage `reference`, cached on
// disk); every configuration is timed (median of N frames after warm-up, glFinish + steady
// clock per stage, summed over the stages the method needs) and compared with the
// reference on one more frame. Writes results.csv, results.md and speed_vs_error.png into
// --out. A benchmark program: it writes numbers and asserts nothing.
#pragma once
#include <string>
#include <vector>

#include "reference/error_metrics.h"

struct BenchOptions {
  std::string scene = "cube";
  std::string preset;               // "" = default
  std::vector<std::string> sweeps;  // "stage.key=v1,v2", "scene.light_scale=...", "eye.size=..."
  std::vector<std::string> sets;    // applied to every configuration first
  std::string out = "bench";
  int width = 0, height = 0;        // 0: the preset's default
  int frames = 10, warmup = 2;
  int rounds = 5;                   // the frames are spread over this many passes (see .cpp)
  int referenceSamples = 16;
  double timeLimit = 900;           // seconds of reference tracing allowed (estimated first)
  std::string commandLine;          // for the report
};

int runBench(const BenchOptions& options);

// One measured configuration.
struct BenchResult {
  size_t setup = 0;                 // index into the plan
  std::string label, method;        // method: "hard_shadow" or "monte_carlo"
  std::string search, layers;       // from the pipeline's parameters after the sets
  int rays = 0, map = 0;
  bool deferred = true, filter = true;
  std::string family;               // "hierarchical 2L", "hard shadow", ... (plot series)
  int frames = 0;
  double msMedian = 0, msMin = 0, msMax = 0;
  double traceMsMedian = 0;         // the trace stage alone (Monte Carlo)
  double fetchesPerRay = 0, raysTraced = 0;
  ErrorMetrics error;
  double referenceSeconds = 0;      // tracing time (0 when cached)
  int referenceCache = 0;           // 0 computed, 1 memory, 2 disk
  bool pareto = false;              // on the frontier of its setup (ms, mean |e| in shadow)
};

// Stages whose times make up a method's milliseconds per frame.
std::vector<std::string> timedStages(const std::string& method, bool filter);

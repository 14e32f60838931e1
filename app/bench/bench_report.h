// `penumbra bench`: speed against error (docs/design.md#bench). For each setup of the plan
// (app/bench/bench_configs.h) the exact reference is computed once (stage `reference`, cached on
// disk); every configuration is timed (median of N frames after warm-up, glFinish + steady
// clock per stage, summed over the stages the method's visibility depends on in the graph)
// and compared with the reference on one more frame. Writes results.json, results.csv,
// results.md and the plots (PNG, SVG, PDF) into --out. A benchmark program: it writes
// numbers and asserts nothing.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "reference/error_metrics.h"

struct BenchOptions {
  std::string scene = "cube";
  double time = 0;                  // --time: the scene posed at this time (scene/animation.h)
  std::string preset;               // "" = default
  std::vector<std::string> sweeps;  // "stage.key=v1,v2", "scene.light_scale=...", "eye.size=..."
  std::vector<std::string> sets;    // applied to every configuration first
  std::string out = "bench";
  int width = 0, height = 0;        // 0: the preset's default
  int frames = 10, warmup = 2;
  int rounds = 5;                   // the frames are spread over this many passes (see .cpp)
  int referenceSamples = 16;
  double fps = 12;                  // preset animated: frames per second over one cycle
  int loopFrames = 0;               // preset animated: only the first N frames (0: all)
  double timeLimit = 900;           // seconds of reference tracing allowed (estimated first)
  std::string commandLine;          // for the report
};

int runBench(const BenchOptions& options);

class Pipeline;

// One measured configuration.
struct BenchResult {
  size_t setup = 0;                 // index into the plan
  std::string label, method;        // method: the stage whose visibility is measured
  std::string family;               // plot series ("hierarchical 2L", or the method's name)
  std::vector<std::string> sets;    // the configuration's assignments (--set ones first)
  std::vector<std::string> stages;  // the stages timed: the method's dependency closure
  std::map<std::string, std::string> params;  // every parameter of those stages, after the sets
  int map = 0;                      // light.resolution
  int frames = 0;
  double msMedian = 0, msMin = 0, msMax = 0;  // summed over `stages`
  std::map<std::string, double> stageMs;      // the median of each timed stage alone
  std::map<std::string, double> counters;     // the timed stages' counters on the error frame
  ErrorMetrics error;
  double referenceSeconds = 0;      // tracing time (0 when cached)
  int referenceCache = 0;           // 0 computed, 1 memory, 2 disk
  bool pareto = false;              // on the frontier of its setup (ms, mean |e| in shadow)
  // The reference as a method (app/bench/bench_reference.h): its BVH builds, median and
  // slowest (ms; part of msMedian only when "bvh_build" is one of `stages`: a moving scene).
  double bvhMsMedian = 0, bvhMsMax = 0;
  // An animated setup's loop (app/bench/bench_animated.h): the time of each timed frame and
  // its milliseconds (msMedian and msMax are their median and worst).
  std::vector<double> loopTimes, loopMs;
  std::vector<double> loopBvhMs;    // the reference rebuilding its BVH: each frame's build

  double counter(const std::string& name) const {
    const auto it = counters.find(name);
    return it == counters.end() ? 0.0 : it->second;
  }
};

// The stages whose times make up a method's milliseconds per frame: every stage its
// visibility depends on under the pipeline's current parameters, in execution order.
std::vector<std::string> timedStages(const Pipeline& pipeline, const std::string& method);

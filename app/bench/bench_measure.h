// Measuring one bench configuration, shared by `penumbra bench` (app/bench/bench_report.cpp)
// and the window's live speed-against-error panel: the configuration's error against the
// ground truth on one frame, then timed frames of only the stages its visibility depends
// on (Pipeline::dependencies of the method's output; glFinish + steady clock per stage).
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench/bench_configs.h"
#include "bench/bench_report.h"

class Pipeline;
struct Frame;
struct Param;
class ReferenceTracer;

// Every parameter's value and auto flag now, restored between configurations.
class ParamSnapshot {
public:
  explicit ParamSnapshot(const Pipeline& pipeline);
  void restore() const;

private:
  struct Saved {
    Param* param;
    double value;
    bool automatic;
  };
  std::vector<Saved> values_;
};

// Applies "stage.key=value" assignments in order; "" or the first problem.
std::string applySets(Pipeline& pipeline, const std::vector<std::string>& sets);

// With the configuration's sets applied: its method, family, timed stages and their
// parameters, and its error against the ground truth on one frame (frame key 0; the
// reference at m x m `referenceSamples`). Returns false while the reference is still being
// traced in the background (reference.background: call again on a later frame). Throws
// std::runtime_error when the frame gives no error metrics. A configuration of the reference
// as a method (referenceSamples > 0) is measured by app/bench/bench_reference.h.
bool measureError(Pipeline& pipeline, Frame& frame, size_t setup, const BenchConfig& config,
                  int referenceSamples, BenchResult& result);

// Collects timed frames of one configuration (its sets applied): each frame runs only the
// method's stages (the reference as a method: bench_reference.h).
struct FrameTimes {
  std::vector<double> totals;                          // ms per frame, summed over the stages
  std::map<std::string, std::vector<double>> stages;  // ms per frame of each timed stage
  // The reference as a method: its BVH (kept between the frames of a static scene) and the
  // milliseconds of each build.
  std::shared_ptr<ReferenceTracer> tracer;
  std::vector<double> bvhMs;
};
void timeFrame(Pipeline& pipeline, Frame& frame, const BenchResult& result, std::uint32_t frameKey,
               FrameTimes* times);  // times == nullptr: a warm-up frame
// Fills the result's frames, median / min / max, per-stage medians and BVH builds.
void summarize(const FrameTimes& times, BenchResult& result);

double median(std::vector<double> values);

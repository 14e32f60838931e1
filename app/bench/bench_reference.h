// The reference as a method on the speed-against-error plots (docs/design.md#bench,
// docs/decisions/125-reference-as-a-bench-method.md): the Embree ray tracer of
// app/reference/reference_trace.h at m x m light samples per pixel, at the cell centres
// (reference.sampling = uniform: the light samples of raster4d at raster4d.samples = m, so
// at equal m the two images agree up to ties at edges), timed and measured like any method:
//  - its time: the stages its rays start from and aim at (the G-buffer, the light frame,
//    as the pipeline times them), the G-buffer's read-back to the CPU, Embree's trace, and,
//    for a moving scene (preset animated: BenchConfig::rebuildBvh), the BVH's build, every
//    frame (Wang et al. §5: on the dynamic Toys "ray tracing has to recompute the BVH for
//    every frame"). On a static scene the BVH is built once and its time reported apart
//    (BenchResult::bvhMsMedian);
//  - its error: against the bench's own truth (stage `reference` at --reference-samples,
//    stratified: independent jitter, so at m x m its error is its sampling error, plus the
//    truth's own, smaller), over the pixels the error stage counts (error.pixels).
// It is no stage of the graph: the window's views never show it; the bench, its report and
// the window's live speed-vs-error panel do.
#pragma once
#include <cstdint>
#include <map>
#include <string>

#include "reference/reference_trace.h"

#include "bench/bench_configs.h"
#include "bench/bench_measure.h"
#include "bench/bench_report.h"

class Pipeline;
struct Frame;

// As measureError (bench_measure.h) for a configuration with referenceSamples > 0.
bool measureReferenceError(Pipeline& pipeline, Frame& frame, size_t setup,
                           const BenchConfig& config, int truthSamples, BenchResult& result);
// As timeFrame for the reference's result. A warm-up frame (times == nullptr) does nothing:
// nothing of its own lives on the GPU.
void timeReferenceFrame(Pipeline& pipeline, Frame& frame, const BenchResult& result,
                        std::uint32_t frameKey, FrameTimes* times);
// Its two halves, for a caller that traces on another thread (the window's live run):
// the GL thread's (the input stages run and timed, the G-buffer read back), then the CPU's
// (the BVH where needed, the trace; the frame's times added to `times`). `scene` is the
// frame's scene; the second half touches no GL and nothing of the frame.
struct ReferenceFrameWork {
  std::map<std::string, double> ms;  // per timed stage
  ReferenceRequest request;
};
ReferenceFrameWork prepareReferenceFrame(Pipeline& pipeline, Frame& frame, const BenchResult& result,
                                         std::uint32_t frameKey);
void finishReferenceFrame(const Scene& scene, const BenchResult& result, ReferenceFrameWork& work,
                          FrameTimes& times);

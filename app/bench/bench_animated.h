// Preset animated (app/bench/bench_configs.h): the timed frames of an animated setup are the
// frames of one whole cycle of its animation, every one posed anew; per-frame times, their
// median and worst frame, go into results.md / .csv / .json and loop.csv
// (docs/design.md#bench, docs/decisions/126-animated-bench-rebuilds-everything.md).
//
// For each time t of setup.loopTimes: the scene posed at t (scene/animation.h poseAt) and
// uploaded as a new GpuScene with a new Frame (decision 090: nothing of an earlier pose is
// kept, so light layers, hierarchies, shadow maps and the reference's BVH are all rebuilt
// from the posed geometry); then every configuration in turn, with its sets: one untimed run
// at this pose (the new frame's textures of its sizes allocate), then one timed frame
// (timeFrame: the method's stages; the reference: G-buffer, read-back, BVH build, trace).
// Posing and uploading are timed apart (charged to no method: every method pays them alike).
// A frame's configurations run back to back, so a change of load on the shared cores hits
// all of them alike.
#pragma once
#include <vector>

#include "bench/bench_configs.h"
#include "bench/bench_measure.h"
#include "bench/bench_report.h"

class Pipeline;

// results[k] is configuration k's result (its error already measured); times[k] receives
// its frames. Returns the milliseconds of posing + uploading each frame.
std::vector<double> timeLoop(Pipeline& pipeline, const ParamSnapshot& defaults,
                             const std::vector<std::string>& sets, const BenchSetup& setup,
                             const std::vector<BenchResult>& results, std::vector<FrameTimes>& times);

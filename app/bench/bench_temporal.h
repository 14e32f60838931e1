// `penumbra bench-temporal` (docs/temporal.md, docs/decisions/120-temporal-stability.md): the
// temporal stability of shadow methods over a range of frames of a scene. Each frame the
// scene is posed at its time (a static scene stays as it is) and every side (a method with
// its `--set`s, under a fixed or a per-frame key) runs on it; the Embree reference runs once
// per frame for all sides. Per side: mean and worst frame-to-frame change of visibility over
// the pixels whose reference did not change, the reference's own change, their ratio, and
// the mean |error| in shadow against the reference. A benchmark program: it measures counts
// and errors, no times, and asserts nothing.
//
// Its own command rather than a table of `penumbra bench`: bench measures each
// configuration's error on one frame at key 0 and times repeated frames of the same pose;
// this measure needs consecutive frames of a moving pose (or a moving key) with the
// reference traced per frame, a different loop over different inputs, and no timing.
#pragma once
#include <string>
#include <vector>

struct BenchTemporalOptions {
  std::string scene = "slow_slide";
  std::string out = "bench/temporal.md";  // and the per-frame rows beside it, .csv
  std::string title;
  int width = 256, height = 192;
  std::string timeRange = "0:2";  // "start:end" in seconds, both frames included
  double fps = 24;
  std::vector<std::string> keys = {"fixed"};  // fixed (key 0), per_frame (key = frame index)
  std::vector<std::string> sets;   // for every side and the reference
  std::vector<std::string> sides;  // "[label=]method[:stage.key=value;...]"; none: every method
  int referenceSamples = 8;        // m: m x m light samples per pixel in the reference
  std::string commandLine;         // written into the table's header
};

// One side of the comparison, parsed (public for tests).
struct TemporalSide {
  std::string label, method;
  std::vector<std::string> sets;  // the side's own, after the common ones
};
// Throws InputError for an empty method.
TemporalSide parseTemporalSide(const std::string& spec);
// "start:end" -> seconds and the frame count at `fps` (start, start + 1/fps, ... <= end).
// Throws InputError naming what is wrong.
int temporalFrames(const std::string& range, double fps, double& start);

int runBenchTemporal(const BenchTemporalOptions& options);

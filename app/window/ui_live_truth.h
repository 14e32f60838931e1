// Which ground truth the window's live error is measured against (docs/raster4d.md).
// Two ground truths exist: Embree on the CPU (`reference`: any scene, traced in the background
// and cached on disk) and 4D rasterization on the GPU (`raster4d`: exact for its m x m grid of
// light samples, computed inside the frame, so the error follows every change at once while
// the scene is small). The window picks raster4d when its cost per run, measured or estimated,
// is interactive, and Embree otherwise; a choice the user made (the `against` parameter set in
// the panel, by --set, a config or a script) is kept and never overridden.
#pragma once
#include <string>
#include <vector>

#include "window/ui_session.h"

// The rule: raster4d when its predicted milliseconds per run are at most this (4 runs a
// second), and it is not itself the method measured.
constexpr double kInteractiveTruthMs = 250;

// raster4d's milliseconds per run estimated before it has run on the scene: a power law fitted
// to docs/raster4d_speed.md's 32x32 rows on llvmpipe (128x128 eye: cube 12 occluder triangles 93
// ms, spheres 3072 -> 2082 ms, engine 121,496 -> 14,426 ms): linear in eye pixels and in the rows m
// (paper Table 4), and occluderTriangles^0.55 (bigger scenes have smaller triangles, so the pairs
// grow slower than the count).
double estimateRaster4dMs(long long eyePixels, int samplesPerSide, long long occluderTriangles);

struct LiveTruth {
  bool automatic = true;  // false once the user chose a ground truth
  std::string chosen;     // what the rule chose last ("" before the first choice)
  std::string seen;       // the choice as last seen: a change the rule did not make is the user's
  double predictedMs = 0;
  bool fromMeasurement = false;  // predictedMs scales a measured run (else the estimate)
  std::string reason;            // one line for the panel and the status line
  // raster4d's last run on this scene: its milliseconds, eye pixels and samples per side.
  double measuredMs = 0;
  long long measuredPixels = 0;
  int measuredSamples = 0, measuredScene = -1;
};

// Before every run: notices a choice the user made; while automatic and the comparison is
// shown, applies the rule (the status line says when the choice changes).
// `shown`: the outputs the window shows; `status`: the status line.
void updateLiveTruth(LiveTruth& truth, Session& session, const std::vector<std::string>& shown,
                     std::string& status);
// After every run: remembers raster4d's time at full resolution.
void recordLiveTruthRun(LiveTruth& truth, const Session& session);
// While automatic: sets the comparison's ground truth by the rule (and enables it); returns
// what it chose ("" when nothing changed).
std::string applyLiveTruthRule(LiveTruth& truth, Session& session);
// The user's choice counts as such from now on (--set error.against=..., the panel's combo).
void keepUserTruth(LiveTruth& truth);
// "against raster4d (automatic: predicted 12 ms <= 250 ms, measured)".
std::string liveTruthLine(const LiveTruth& truth, const Pipeline& pipeline);

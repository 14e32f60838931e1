// `penumbra trace --scene S --pixel X,Y`: every step of every ray at one pixel, as JSON
// (app/export/trace_json.h formats them; the same records the window's per-ray panel draws).
#pragma once
#include <string>
#include <vector>

struct TraceOptions {
  std::string scene = "cube";
  std::string pixel;  // "X,Y", image coordinates (row 0 at the top, as in the PNGs)
  std::string out;    // file; empty: stdout
  int width = 512, height = 512;
  std::vector<std::string> sets;
  double time = 0;  // --time: seconds into the scene's animation
};

int runTraceCommand(const TraceOptions& options);

// `penumbra trace --scene S --pixel X,Y`: every step of every ray at one pixel, as JSON
// (the same records the window's per-ray panel draws).
#pragma once
#include <string>
#include <vector>

#include "core/frame.h"

struct TraceOptions {
  std::string scene = "cube";
  std::string pixel;  // "X,Y", image coordinates (row 0 at the top, as in the PNGs)
  std::string out;    // file; empty: stdout
  int width = 512, height = 512;
  std::vector<std::string> sets;
  double time = 0;  // --time: seconds into the scene's animation
};

int runTraceCommand(const TraceOptions& options);

// The name of a STEP_* decision ("descend", "hit", ...).
const char* stepDecisionName(int decision);
// The recorded steps of `frame` as JSON text, grouped by ray, with the pixel's visibility
// and the image size the pixel is in ("image_size": [width, height]).
std::string traceStepsJson(const Frame& frame, int x, int y);

// The command that records the same steps headless: image pixel (x, y) (row 0 at the top)
// of a width x height eye image, the scene as loaded, `sets` as stage.key=value. The window's
// ray trace panel shows it, so a pixel picked in a 616x665 view is the CLI's pixel too.
// A non-zero `time` (an animated scene's pose) is given as --time.
std::string traceCommandLine(const std::string& scene, int x, int y, int width, int height,
                             const std::vector<std::string>& sets, double time = 0);

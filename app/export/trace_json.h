// The trace's recorded steps of one pixel as JSON, and the command line that records them
// headless: shared by `penumbra trace` (app/cli/trace_command.h) and the window's ray trace
// panel (the same records it draws).
#pragma once
#include <string>
#include <vector>

#include "core/frame.h"

// The name of a STEP_* decision ("descend", "hit", ...).
const char* stepDecisionName(int decision);
// The recorded steps of `frame` as JSON text, grouped by ray, with the pixel's visibility
// and the image size the pixel is in ("image_size": [width, height]).
std::string traceStepsJson(const Frame& frame, int x, int y);

// The command that records the same steps headless: image pixel (x, y) (row 0 at the top)
// of a width x height eye image, the scene as loaded, `sets` as stage.key=value. The window's
// ray trace panel shows it, so a pixel picked in a 616x665 view is the CLI's pixel too.
std::string traceCommandLine(const std::string& scene, int x, int y, int width, int height,
                             const std::vector<std::string>& sets, double time = 0);

// HOOK: the per-ray march trace panel (issue 4, "Stage-specific views").
//
// The trace stage records every step of one ray; this panel draws those steps without
// knowing the search: a table, a plot of ray depth against step with each visited
// neighbourhood's [zNearMin, zFarMax] band, and rectangles over views of the N-buffer.
// To connect it, the trace stage's owner converts its step records to RayStepRecord and
// installs a source once (e.g. next to makeStages()):
//
//     rayTraceSource() = [](const Frame& frame, glm::ivec2 pixel, int ray) {
//       return convert(recordSteps(frame, pixel, ray));  // -> std::vector<RayStepRecord>
//     };
//
// Until then the panel says that no trace source is installed.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

struct Frame;

// One step of one ray's march through the N-buffer (thesis §3.6-3.7), in light space.
struct RayStepRecord {
  int level = 0;                   // N-buffer level of the visited neighbourhood
  glm::ivec2 windowLo{0}, windowHi{0};  // its level-0 texel window, inclusive
  float rayDepthEnter = 0, rayDepthExit = 0;  // ray's lsDepth over the step's span
  float zNearMin = 0, zNearMax = 0, zFarMax = 0;  // the neighbourhood's depths (lsDepth)
  std::string decision;            // "skip", "descend", "hit", "refine", "sample"...
};

struct RayTraceInfo {
  int raysPerPixel = 0;            // n x n
  std::vector<RayStepRecord> steps;
  std::string result;              // "visible", "blocked", ... (free text)
};

using RayTraceSource = std::function<RayTraceInfo(const Frame&, glm::ivec2 pixel, int ray)>;
RayTraceSource& rayTraceSource();  // empty until the trace stage installs one

// A rectangle over views whose texture has size `space` (texel coordinates, inclusive).
struct ViewOverlayRect {
  glm::ivec2 space{0}, lo{0}, hi{0};
  unsigned color = 0xff00ffff;  // ImGui ABGR
};

// Draws the panel for `steps`; fills `overlay` with the visited windows, coloured by level.
void drawRayTracePanel(const RayTraceInfo& trace, glm::ivec2 lightMapSize,
                       std::vector<ViewOverlayRect>& overlay);
// The colour of N-buffer level `level` in plots and rectangles (ImGui ABGR).
unsigned levelColor(int level);

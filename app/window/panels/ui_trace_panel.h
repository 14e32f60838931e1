// HOOK: the per-ray march trace panel (docs/design.md#window).
//
// The trace stage records every step of one pixel's rays; this panel draws those steps
// without knowing the search: a table, a plot of ray depth against step with each visited
// neighbourhood's [zNearMin, zFarMax] band, and the visited windows as rectangles (plus the
// ray's projected path) over views of light-map size (the layers, the N-buffer levels).
// The steps come from the views' traceSource (ViewState, ui_view_state.h);
// app/window/views/ui_trace_source.cpp installs the one that reads
// the recorded steps (stages/monte_carlo/trace/trace_steps.h) (recorded for trace.record_x / record_y, which the window sets from the
// pick). Another search can install its own:
//
//     state.views.traceSource = [](const Frame& frame, glm::ivec2 pixel, int ray) {
//       return RayTraceInfo{...};  // steps converted to RayStepRecord
//     };
//
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

struct Frame;

// One step of one ray's march through the N-buffer (thesis §3.6-3.7), in light space.
struct RayStepRecord {
  int level = 0;                   // N-buffer level of the visited neighbourhood (-1: none)
  glm::ivec2 windowLo{0}, windowHi{0};  // its level-0 texel window (GL texels), inclusive
  float rayDepthEnter = 0, rayDepthExit = 0;  // ray's lsDepth over the step's span
  float zNearMin = 0, zFarMax = 0;  // the neighbourhood's depth band (lsDepth)
  glm::vec2 texelPoint{-1};        // the ray's projection at the step's end (level-0 texels)
  std::string decision;            // "descend", "advance", "hit", "sample", "refine"...
  // Point samples (linear and linear_binary search, §3.2-3.3): one point of the ray, not a
  // window. Drawn as a dot at `texelPoint` (white: sample, orange: refinement, red: hit) and,
  // in the plot, at x = `stepping` with [zNearMin, zFarMax] = the layers' [near, far] at the
  // sample's texel (the solid the sample is tested against).
  bool point = false;
  bool refinement = false;         // a binary-refinement point (between two samples)
  float stepping = -1;             // s at the step's end: 0 at the light, 1 at the receiver
};

struct RayTraceInfo {
  int raysPerPixel = 0;            // n x n
  std::vector<RayStepRecord> steps;
  std::string result;              // "visible", "blocked", ... (free text)
  std::string commandLine;         // the `penumbra trace` that records the same pixel (or "")
  std::string commandNote;         // why it may differ (a moved camera), or ""
};

struct UiState;
// The `penumbra trace` command of the picked pixel at the view's eye size, the loaded scene
// and every parameter set away from its default (app/export/trace_json.h); a note when the camera
// or the light moved since the scene loaded (the command uses the scene's).
void describeTraceCommand(const UiState& state, RayTraceInfo& trace);

// Held by the views (ViewState::traceSource), empty until one is installed
// (app/window/views/ui_trace_source.h).
using RayTraceSource = std::function<RayTraceInfo(const Frame&, glm::ivec2 pixel, int ray)>;

// A shape over views whose texture has size `space`, in continuous texel coordinates
// (texel (i, j) covers [i, i+1] x [j, j+1], GL rows): a rectangle with corners a, b, or a
// line from a to b.
struct ViewOverlayShape {
  glm::ivec2 space{0};
  glm::vec2 a{0}, b{0};
  unsigned color = 0xff00ffff;  // ImGui ABGR
  bool line = false;
  float dot = 0;                // > 0: a dot of this radius (screen pixels) at `a`
};

// Draws the panel for `trace`; fills `overlay` with the visited windows (coloured by level),
// the point samples (dots) and the ray's projected path.
void drawRayTracePanel(const RayTraceInfo& trace, glm::ivec2 lightMapSize,
                       std::vector<ViewOverlayShape>& overlay);
// The colour of N-buffer level `level` in plots and rectangles (ImGui ABGR).
unsigned levelColor(int level);
// The colour of a point sample: white sample, orange refinement, red hit (ImGui ABGR).
unsigned pointColor(const RayStepRecord& step);
// The overlay shapes of `trace` over views of size `lightMapSize` (what the panel draws).
std::vector<ViewOverlayShape> traceOverlay(const RayTraceInfo& trace, glm::ivec2 lightMapSize);

// The window's views: up to four texture views of the centre area (one, A|B side by side, or
// a 2x2 grid to compare four methods), the selection, the pick and what is drawn over the
// views (one part of UiState, app/window/ui_state.h).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "window/panels/ui_trace_panel.h"
#include "window/views/ui_categories.h"
#include "window/views/texture_view.h"
#include "window/views/ui_view_difference.h"
#include "window/views/ui_view_settings.h"
#include "window/views/ui_view_transform.h"

// One texture view of the centre area.
struct ViewPanel {
  std::string output;         // "stage.output" shown
  bool locked = false;        // a locked view ignores selections in the pipeline panel
  bool toolsOpen = false;     // the 2x2 grid shows only the output unless the tools are open
  ViewSettings settings;
  std::string settingsFor;    // the output `settings` were initialised from
  ViewTransform transform;
  bool fitPending = true;     // fit on the next draw (new output, new size, "Fit")
  bool fitted = false;        // still as fitted (no zoom / pan since): refit on resize
  bool autofitPending = false;
  glm::vec2 regionSize{0, 0};  // the image region drawn last frame (screen pixels)
  glm::vec2 eyeRegion{0, 0};   // the view's area less a fixed toolbar reserve: "fit view" eye
  glm::ivec2 lastTextureSize{0, 0};  // to keep the picture in place when the size changes
  glm::vec2 regionOrigin{0, 0};  // top-left of the image region last frame (window pixels)
  bool frameOverlays = false;  // zoom onto the ray trace's shapes once they are drawn here
  TextureView renderer;
  // Difference view (app/window/views/ui_view_difference.h): shows output - minus when minus is set.
  std::string minus;
  bool clipNegative = false;  // negative differences shown as 0 (thickness: uncovered texels)
  mutable ViewDifference difference;  // a cache of the GPU result
  mutable ViewLevel level;  // the shown mip level of a mipmapped output (ui_view_difference.h)
  mutable CategoryCounts categories;  // the categorical legend's counts (ui_categories.h)
};

// The picked pixel's occlusion mask drawn on the light (ui_light_gesture.cpp), read back
// once per pipeline run: `side` x `side` values, GL order (side 0: nothing to draw).
struct LightMaskCache {
  std::vector<float> mask;
  int run = -1, side = 0;
};

// How the centre area is split: one view, A | B, or A B / C D.
enum class ViewLayout { One, SideBySide, Grid };
constexpr int kMaxViews = 4;

struct ViewState {
  ViewPanel panels[kMaxViews];
  int activeView = 0;
  ViewLayout layout = ViewLayout::One;
  bool linked = false;  // zoom and pan of one view apply to the others (same relative place)
  std::string selectedStage;
  std::string scrollToStage;  // the pipeline panel brings this stage into view (scripts, views)
  std::optional<glm::ivec2> pick;  // GL texel (row 0 at the bottom) in a texture of `pickSpace`
  glm::ivec2 pickSpace{0, 0};
  glm::vec2 pickUv{0, 0};  // the pick's centre over pickSpace: kept exactly while the eye resizes
  int selectedRay = 0;
  std::vector<ViewOverlayShape> overlays;  // drawn by views of matching size (ray trace)
  bool showLight = true;    // the light's outline over eye-sized views (ui_light_gesture.h)
  mutable LightMaskCache lightMask;  // what the outline draws of the picked pixel's mask
  bool traceShown = false;  // the inspector's ray trace section is open (it needs the trace)
  bool traceWindow = false;  // the ray trace panel in its own window instead of the inspector
  RayTraceSource traceSource;  // the panel's steps of one ray; empty until installed (ui_trace_source.h)

  // 1. Layout: how many views are shown; opening a view copies what A shows into a view
  //    that shows nothing yet (so nothing new has to run).
  int shownViews() const { return layout == ViewLayout::One ? 1 : layout == ViewLayout::SideBySide ? 2 : 4; }
  void setLayout(ViewLayout next);
  // The view a pipeline-panel selection goes to: the active one unless locked, else the
  // next shown one that is not.
  ViewPanel* selectionTarget();
  // 2. The pick stays inside the texture it was made in; `followResize` moves it to the same
  //    place of a resized texture (the eye when a view opens under "fit view").
  void setPick(glm::ivec2 texel, glm::ivec2 space);
  void movePick(glm::ivec2 delta);
  void followResize(glm::ivec2 from, glm::ivec2 to);
  // 3. Linked views: the other shown views take view `from`'s zoom and pan, scaled to their
  //    texture size (same relative centre, same screen size of the whole image).
  void linkFrom(int from);
};

const char* layoutName(ViewLayout layout);  // "one", "side_by_side", "grid"
bool layoutFromName(const std::string& name, ViewLayout& layout);

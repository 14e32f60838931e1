// The window's views: the two texture views of the centre area, the selection, the pick and
// what is drawn over the views (one part of UiState, app/window/ui_state.h).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "window/panels/ui_trace_panel.h"
#include "window/views/texture_view.h"
#include "window/views/ui_view_difference.h"
#include "window/views/ui_view_settings.h"
#include "window/views/ui_view_transform.h"

// One texture view of the centre area.
struct ViewPanel {
  std::string output;         // "stage.output" shown
  bool locked = false;        // a locked view ignores selections in the pipeline panel
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
};

struct ViewState {
  ViewPanel panels[2];
  int activeView = 0;
  bool twoViews = false;
  std::string selectedStage;
  std::string scrollToStage;  // the pipeline panel brings this stage into view (scripts, views)
  std::optional<glm::ivec2> pick;  // GL texel (row 0 at the bottom) in a texture of `pickSpace`
  glm::ivec2 pickSpace{0, 0};
  int selectedRay = 0;
  std::vector<ViewOverlayShape> overlays;  // drawn by views of matching size (ray trace)
  bool showLight = true;    // the light's outline over eye-sized views (ui_light_gesture.h)
  bool traceShown = false;  // the inspector's ray trace section is open (it needs the trace)
  bool traceWindow = false;  // the ray trace panel in its own window instead of the inspector

  // The view a pipeline-panel selection goes to: the active one unless locked.
  ViewPanel* selectionTarget();
  // The pick stays inside the texture it was made in.
  void setPick(glm::ivec2 texel, glm::ivec2 space);
  void movePick(glm::ivec2 delta);
};

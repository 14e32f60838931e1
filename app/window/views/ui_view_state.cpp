#include "window/views/ui_view_state.h"

// The active view takes a selection unless locked, then the other one.
ViewPanel* ViewState::selectionTarget() {
  if (!panels[activeView].locked) return &panels[activeView];
  const int other = 1 - activeView;
  if (twoViews && !panels[other].locked) return &panels[other];
  return nullptr;
}

void ViewState::setPick(glm::ivec2 texel, glm::ivec2 space) {
  if (space.x <= 0 || space.y <= 0) return;
  pick = glm::clamp(texel, glm::ivec2(0), space - 1);
  pickSpace = space;
}

void ViewState::movePick(glm::ivec2 delta) {
  if (pick) setPick(*pick + delta, pickSpace);
}

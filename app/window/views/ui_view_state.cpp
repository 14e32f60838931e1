#include "window/views/ui_view_state.h"

#include <cmath>

// 1. Layout.
void ViewState::setLayout(ViewLayout next) {
  layout = next;
  for (int v = 1; v < shownViews(); ++v)
    if (panels[v].output.empty()) panels[v].output = panels[0].output;
  if (activeView >= shownViews()) activeView = 0;
}

const char* layoutName(ViewLayout layout) {
  return layout == ViewLayout::One ? "one" : layout == ViewLayout::SideBySide ? "side_by_side" : "grid";
}

bool layoutFromName(const std::string& name, ViewLayout& layout) {
  for (ViewLayout candidate : {ViewLayout::One, ViewLayout::SideBySide, ViewLayout::Grid})
    if (name == layoutName(candidate)) {
      layout = candidate;
      return true;
    }
  return false;
}

// The active view takes a selection unless locked, then the next shown one.
ViewPanel* ViewState::selectionTarget() {
  for (int i = 0; i < shownViews(); ++i) {
    ViewPanel& view = panels[(activeView + i) % shownViews()];
    if (!view.locked) return &view;
  }
  return nullptr;
}

// 2. The pick.
void ViewState::setPick(glm::ivec2 texel, glm::ivec2 space) {
  if (space.x <= 0 || space.y <= 0) return;
  pick = glm::clamp(texel, glm::ivec2(0), space - 1);
  pickSpace = space;
  pickUv = (glm::vec2(*pick) + 0.5f) / glm::vec2(space);
}

void ViewState::movePick(glm::ivec2 delta) {
  if (pick) setPick(*pick + delta, pickSpace);
}

void ViewState::followResize(glm::ivec2 from, glm::ivec2 to) {
  if (!pick || pickSpace != from || from == to || to.x <= 0 || to.y <= 0) return;
  pick = glm::clamp(glm::ivec2(glm::floor(pickUv * glm::vec2(to))), glm::ivec2(0), to - 1);
  pickSpace = to;  // pickUv stays: back at the old size, the pick is exactly where it was
}

// 3. Linked zoom and pan, relative to each view's texture.
void ViewState::linkFrom(int from) {
  const ViewPanel& source = panels[from];
  const glm::vec2 sourceSize(source.lastTextureSize);
  if (sourceSize.x <= 0 || sourceSize.y <= 0) return;
  for (int v = 0; v < shownViews(); ++v) {
    ViewPanel& view = panels[v];
    const glm::vec2 size(view.lastTextureSize);
    if (v == from || size.x <= 0 || size.y <= 0) continue;
    const glm::vec2 ratio = size / sourceSize;  // exactly 1 for views of the same size
    view.transform.zoom = source.transform.zoom / ratio.x;
    view.transform.center = source.transform.center * ratio;
    view.fitPending = false;
    view.fitted = source.fitted;
  }
}

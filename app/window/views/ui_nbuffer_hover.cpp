#include "window/views/ui_nbuffer_hover.h"

#include <algorithm>

#include "gl/hierarchy_cells.h"

glm::ivec2 nbufferWindow1D(int level, int x, int size) {
  // A level past the map's (a view's "level" is the user's; 1 << 40 is undefined) spans
  // the whole map, as the top level does.
  return cells::nbufferWindow1D(std::clamp(level, 0, 30), x, size);
}

void nbufferWindow(int level, glm::ivec2 texel, glm::ivec2 size, glm::ivec2& lo, glm::ivec2& hi) {
  const glm::ivec2 x = nbufferWindow1D(level, texel.x, size.x);
  const glm::ivec2 y = nbufferWindow1D(level, texel.y, size.y);
  lo = {x.x, y.x};
  hi = {x.y, y.y};
}

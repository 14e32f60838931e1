#include "window/views/ui_nbuffer_hover.h"

#include <algorithm>

// nbuffer.glsl: a_n = 2^n / 2 (a_0 = 0); lo = clamp(x - a_n, 0, max(size - 2^n, 0)).
glm::ivec2 nbufferWindow1D(int level, int x, int size) {
  // A level past the map's (a view's "level" is the user's; 1 << 40 is undefined) spans
  // the whole map, as the top level does.
  level = std::clamp(level, 0, 30);
  const int span = 1 << level;
  const int half = level == 0 ? 0 : 1 << (level - 1);
  const int lo = std::clamp(x - half, 0, std::max(size - span, 0));
  return {lo, std::min(lo + span, size) - 1};
}

void nbufferWindow(int level, glm::ivec2 texel, glm::ivec2 size, glm::ivec2& lo, glm::ivec2& hi) {
  const glm::ivec2 x = nbufferWindow1D(level, texel.x, size.x);
  const glm::ivec2 y = nbufferWindow1D(level, texel.y, size.y);
  lo = {x.x, y.x};
  hi = {x.y, y.y};
}

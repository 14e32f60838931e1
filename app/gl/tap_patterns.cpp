#include "gl/tap_patterns.h"

#include <algorithm>
#include <limits>
#include <random>

std::vector<glm::vec2> squareTaps(TapPattern pattern, int perSide) {
  std::vector<glm::vec2> taps;
  const int count = perSide * perSide;
  if (pattern == TapPattern::Regular) {
    for (int j = 0; j < perSide; ++j)
      for (int i = 0; i < perSide; ++i)
        taps.push_back(glm::vec2((i + 0.5f) / perSide, (j + 0.5f) / perSide) * 2.0f - 1.0f);
    return taps;
  }
  std::mt19937 rng(2005);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  while (int(taps.size()) < count) {
    glm::vec2 best{};
    float bestDistance = -1;
    for (int candidate = 0; candidate < 16; ++candidate) {
      const glm::vec2 p(uniform(rng), uniform(rng));
      float nearest = std::numeric_limits<float>::max();
      for (const glm::vec2& q : taps) nearest = std::min(nearest, glm::dot(p - q, p - q));
      if (nearest > bestDistance) bestDistance = nearest, best = p;
    }
    taps.push_back(best);
  }
  return taps;
}

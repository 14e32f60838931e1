// Random layers: bumps and plateaus are unioned the way rasterized layers combine (near = the
// front-most front face, far = the back-most back face); sheets and holes overwrite.
#include "support/layer_oracle_fields.h"

#include <algorithm>
#include <cmath>
#include <random>

LayerMaps randomLayers(int width, int height, uint32_t seed, const RandomLayerOptions& options) {
  LayerMaps maps = emptyLayers(width, height);
  std::mt19937 random(seed);
  auto uniform = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(random); };
  auto depth = [&] { return uniform(options.minDepth, options.maxDepth); };
  auto index = [&](int x, int y) { return size_t(y) * width + x; };
  auto unite = [&](int x, int y, float nearDepth, float farDepth) {
    const size_t i = index(x, y);
    maps.nearLayer[i] = std::min(maps.nearLayer[i], nearDepth);
    maps.farLayer[i] = std::max(maps.farLayer[i], farDepth);
  };
  // A random rectangle [x0, x1) x [y0, y1) of up to a third of the map per side.
  auto rectangle = [&](int& x0, int& y0, int& x1, int& y1) {
    x0 = std::uniform_int_distribution<int>(0, width - 1)(random);
    y0 = std::uniform_int_distribution<int>(0, height - 1)(random);
    x1 = std::min(width, x0 + 1 + std::uniform_int_distribution<int>(0, std::max(1, width / 3))(random));
    y1 = std::min(height, y0 + 1 + std::uniform_int_distribution<int>(0, std::max(1, height / 3))(random));
  };

  for (int b = 0; b < options.bumps; ++b) {
    const float cx = uniform(0, width), cy = uniform(0, height);
    const float sigma = uniform(1.0f, 0.2f * std::max(width, height) + 1.5f);
    const float top = depth(), span = uniform(0.05f, 0.4f), thickness = uniform(0.0f, 0.3f);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const float r2 = (x + 0.5f - cx) * (x + 0.5f - cx) + (y + 0.5f - cy) * (y + 0.5f - cy);
        const float profile = std::exp(-r2 / (2 * sigma * sigma));
        if (profile < 0.1f) continue;
        const float nearDepth = std::min(options.maxDepth, top + span * (1 - profile));
        unite(x, y, nearDepth, std::min(options.maxDepth, nearDepth + thickness * profile));
      }
  }
  int x0, y0, x1, y1;
  for (int p = 0; p < options.plateaus; ++p) {
    rectangle(x0, y0, x1, y1);
    const float a = depth(), b = depth();
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) unite(x, y, std::min(a, b), std::max(a, b));
  }
  for (int s = 0; s < options.sheets; ++s) {
    rectangle(x0, y0, x1, y1);
    const float d = depth();
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) maps.nearLayer[index(x, y)] = maps.farLayer[index(x, y)] = d;
  }
  for (int h = 0; h < options.holes; ++h) {
    rectangle(x0, y0, x1, y1);
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) maps.nearLayer[index(x, y)] = 1, maps.farLayer[index(x, y)] = 0;
  }
  const int both = int(std::lround(options.bothFraction * width * height));
  for (int k = 0; k < both; ++k) {
    const int x = std::uniform_int_distribution<int>(0, width - 1)(random);
    const int y = std::uniform_int_distribution<int>(0, height - 1)(random);
    const float a = depth(), b = depth();
    maps.nearLayer[index(x, y)] = std::max(a, b) + 0.01f;  // strictly behind the far value
    maps.farLayer[index(x, y)] = std::min(a, b);
  }
  return maps;
}

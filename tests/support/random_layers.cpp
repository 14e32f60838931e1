#include "random_layers.h"

#include <random>
#include <utility>

Layers randomLayers(int width, int height, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  Layers layers{width, height, {}, {}};
  for (int i = 0; i < width * height; ++i) {
    const float kind = unit(random);
    float a = unit(random), b = unit(random);
    if (kind < 0.25f) { a = 1.0f; b = 0.0f; }                 // empty
    else if (kind < 0.35f) { if (a < b) std::swap(a, b); }   // near > far
    else if (a > b) std::swap(a, b);                          // near <= far
    layers.nearDepth.push_back(a);
    layers.farDepth.push_back(b);
  }
  return layers;
}

GlTexture uploadDepth(const std::vector<float>& values, int width, int height) {
  GlTexture texture(GL_DEPTH_COMPONENT32F, width, height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(texture.id(), 0, 0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT,
                      values.data());
  return texture;
}

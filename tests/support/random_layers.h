// Random light layers for the hierarchy tests (N-buffer, min-max mipmap): empty texels
// (near 1, far 0), ordinary ones (near <= far) and some with near > far, which a hierarchy
// must carry through like any other values; and their upload as depth textures.
#pragma once
#include <vector>

#include "gl/gl_texture.h"

struct Layers {
  int width, height;
  std::vector<float> nearDepth, farDepth;
};

Layers randomLayers(int width, int height, unsigned seed);
GlTexture uploadDepth(const std::vector<float>& values, int width, int height);

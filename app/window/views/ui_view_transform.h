// Zoom and pan of a texture view: which texel is under which screen point. Texel space is
// GL's: texel (i, j) covers [i, i+1] x [j, j+1], j = 0 at the bottom (as texelFetch and the
// stages' pixel coordinates); the screen's y grows downwards.
#pragma once
#include <glm/glm.hpp>

struct ViewTransform {
  float zoom = 1;            // screen pixels per texel
  glm::vec2 center{0, 0};    // texel-space point at the centre of the view region

  // 1. Mapping both ways, for a region with top-left `origin` and `size` (screen pixels).
  glm::vec2 screenFromTexel(glm::vec2 texel, glm::vec2 origin, glm::vec2 size) const;
  glm::vec2 texelFromScreen(glm::vec2 screen, glm::vec2 origin, glm::vec2 size) const;
  // The integer texel under a screen point (may lie outside the texture).
  glm::ivec2 texelAt(glm::vec2 screen, glm::vec2 origin, glm::vec2 size) const;

  // 2. Whole texture in the region, centred; or one texel per screen pixel.
  void fit(glm::vec2 textureSize, glm::vec2 regionSize);
  void oneToOne() { zoom = 1; }
  // 3. Multiplies the zoom by `factor` keeping the texel under `screen` in place.
  void zoomAbout(float factor, glm::vec2 screen, glm::vec2 origin, glm::vec2 size);
  // 4. Moves the image by a screen-space drag.
  void pan(glm::vec2 screenDelta) { center -= glm::vec2(screenDelta.x, -screenDelta.y) / zoom; }
  // 5. Visible texel rectangle [lo, hi) clamped to the texture.
  void visibleTexels(glm::vec2 regionSize, glm::ivec2 textureSize, glm::ivec2& lo,
                     glm::ivec2& hi) const;
};

constexpr float kMinZoom = 1.0f / 64, kMaxZoom = 256;
// Zoom at or above which the texel grid is drawn.
constexpr float kGridZoom = 8;

#include "window/views/ui_view_transform.h"

#include <algorithm>
#include <cmath>

// 1. screen = region centre + (texel - centre) * zoom, with y flipped.
glm::vec2 ViewTransform::screenFromTexel(glm::vec2 texel, glm::vec2 origin, glm::vec2 size) const {
  const glm::vec2 offset = (texel - center) * zoom;
  return origin + 0.5f * size + glm::vec2(offset.x, -offset.y);
}

glm::vec2 ViewTransform::texelFromScreen(glm::vec2 screen, glm::vec2 origin, glm::vec2 size) const {
  const glm::vec2 offset = screen - origin - 0.5f * size;
  return center + glm::vec2(offset.x, -offset.y) / zoom;
}

glm::ivec2 ViewTransform::texelAt(glm::vec2 screen, glm::vec2 origin, glm::vec2 size) const {
  const glm::vec2 texel = texelFromScreen(screen, origin, size);
  return {int(std::floor(texel.x)), int(std::floor(texel.y))};
}

// 2. Fit: the larger relative side fills the region.
void ViewTransform::fit(glm::vec2 textureSize, glm::vec2 regionSize) {
  if (textureSize.x <= 0 || textureSize.y <= 0 || regionSize.x <= 0 || regionSize.y <= 0) return;
  zoom = std::clamp(std::min(regionSize.x / textureSize.x, regionSize.y / textureSize.y),
                    kMinZoom, kMaxZoom);
  center = 0.5f * textureSize;
}

// 3. Keep the point under the cursor fixed: solve for the new centre.
void ViewTransform::zoomAbout(float factor, glm::vec2 screen, glm::vec2 origin, glm::vec2 size) {
  const glm::vec2 anchor = texelFromScreen(screen, origin, size);
  zoom = std::clamp(zoom * factor, kMinZoom, kMaxZoom);
  const glm::vec2 offset = screen - origin - 0.5f * size;
  center = anchor - glm::vec2(offset.x, -offset.y) / zoom;
}

// 5. The texels any part of which is on screen.
void ViewTransform::visibleTexels(glm::vec2 regionSize, glm::ivec2 textureSize, glm::ivec2& lo,
                                  glm::ivec2& hi) const {
  const glm::vec2 half = 0.5f * regionSize / zoom;
  lo = glm::clamp(glm::ivec2(glm::floor(center - half)), glm::ivec2(0), textureSize);
  hi = glm::clamp(glm::ivec2(glm::ceil(center + half)), glm::ivec2(0), textureSize);
}

#include "gl/minmax_build.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "gl/gpu_layout.h"
#include "gl/hierarchy_cells.h"
#include "shared/minmax_layout.h"

static_assert(gpu::distinctBelow({MINMAX_NEAR_UNIT, MINMAX_FAR_UNIT}, gpu::kTextureUnits));
static_assert(MINMAX_ATLAS_IMAGE < gpu::kImageUnits);

int minmaxTopLevel(int width, int height) { return cells::levelSpanning(std::max(width, height)); }

glm::ivec2 minmaxLevelSize(int level, int width, int height) {
  return {cells::minmaxLevelSize(level, width), cells::minmaxLevelSize(level, height)};
}

glm::ivec2 minmaxLevelOrigin(int level, int width, int height) {
  return cells::minmaxLevelOrigin(level, {width, height});
}

glm::ivec2 minmaxAtlasSize(int width, int height) {
  const int top = minmaxTopLevel(width, height);
  if (top == 0) return {1, 1};  // a 1 x 1 map: level 0 alone, the layers
  return {(width + 1) / 2, minmaxLevelOrigin(top + 1, width, height).y};
}

void MinMaxBuilder::build(const GlTexture& nearLayer, const GlTexture& farLayer,
                          GlTexture& atlas) {
  const int width = nearLayer.width(), height = nearLayer.height();
  if (width < 1 || height < 1 || farLayer.width() != width || farLayer.height() != height ||
      nearLayer.isArray() || farLayer.isArray())
    throw std::invalid_argument("buildMinMax: near and far layers must be 2D textures of the "
                                "same size >= 1x1");
  const glm::ivec2 atlasSize = minmaxAtlasSize(width, height);
  if (atlas.internalFormat() != GL_RGBA32F || atlas.isArray() || atlas.width() != atlasSize.x ||
      atlas.height() != atlasSize.y)
    throw std::invalid_argument("buildMinMax: the atlas must be an RGBA32F 2D texture of " +
                                std::to_string(atlasSize.x) + "x" + std::to_string(atlasSize.y) +
                                " (minmaxAtlasSize)");
  // 1. Texels of the atlas outside every level are (0, 0, 0, 0); nothing reads them. Only
  //    those are cleared (right of each level >= 2; all of a 1 x 1 map's atlas).
  const int top = minmaxTopLevel(width, height);
  const float zeros[4] = {0, 0, 0, 0};
  if (top == 0) glClearTexImage(atlas.id(), 0, GL_RGBA, GL_FLOAT, zeros);
  for (int level = 2; level <= top; ++level) {
    const glm::ivec2 origin = minmaxLevelOrigin(level, width, height);
    const glm::ivec2 size = minmaxLevelSize(level, width, height);
    glClearTexSubImage(atlas.id(), 0, size.x, origin.y, 0, atlasSize.x - size.x, size.y, 1,
                       GL_RGBA, GL_FLOAT, zeros);
  }
  // 2. Level 1 from the layers, then level n from level n-1, each drawn over its rectangle
  //    of the atlas; the texture barrier makes the previous level's writes visible.
  glBindTextureUnit(MINMAX_NEAR_UNIT, nearLayer.id());
  glBindTextureUnit(MINMAX_FAR_UNIT, farLayer.id());
  glBindImageTexture(MINMAX_ATLAS_IMAGE, atlas.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
  for (int level = 1; level <= top; ++level) {
    const char* fromLayers = level == 1 ? "1" : "0";
    levelPrograms_[std::string("#define MINMAX_FROM_LAYERS ") + fromLayers + "\n"].use();
    // Uniforms are per program: set for each level.
    glUniform2i(MINMAX_SIZE_LOCATION, width, height);
    glUniform1i(MINMAX_LEVEL_LOCATION, level);
    glTextureBarrier();
    screen_.drawRect(atlas, minmaxLevelOrigin(level, width, height),
                     minmaxLevelSize(level, width, height));
  }
  // Framebuffer writes only: later commands see them without a memory barrier.
}

void buildMinMax(const GlTexture& nearLayer, const GlTexture& farLayer, GlTexture& atlas) {
  static MinMaxBuilder* builder = new MinMaxBuilder;  // never deleted: see the header
  builder->build(nearLayer, farLayer, atlas);
}

#include "shared_inputs/minmax/minmax_build.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "gl/gpu_layout.h"
#include "gl/hierarchy_cells.h"
#include "shared_inputs/minmax/minmax_layout.h"

static_assert(gpu::distinctBelow({MINMAX_NEAR_UNIT, MINMAX_FAR_UNIT, MINMAX_FINER_UNIT},
                                 gpu::kTextureUnits));

int minmaxTopLevel(int width, int height) { return cells::levelSpanning(std::max(width, height)); }

glm::ivec2 minmaxLevelSize(int level, int width, int height) {
  return {cells::minmaxLevelSize(level, width), cells::minmaxLevelSize(level, height)};
}

glm::ivec2 minmaxBaseSize(int width, int height) {
  return {cells::minmaxBaseSize(width), cells::minmaxBaseSize(height)};
}

int minmaxMipLevels(int width, int height) { return cells::minmaxMipLevels({width, height}); }

void MinMaxBuilder::build(const GlTexture& nearLayer, const GlTexture& farLayer,
                          GlTexture& levels) {
  const int width = nearLayer.width(), height = nearLayer.height();
  if (width < 1 || height < 1 || farLayer.width() != width || farLayer.height() != height ||
      nearLayer.isArray() || farLayer.isArray())
    throw std::invalid_argument("buildMinMax: near and far layers must be 2D textures of the "
                                "same size >= 1x1");
  const glm::ivec2 base = minmaxBaseSize(width, height);
  const int mips = minmaxMipLevels(width, height);
  if (levels.internalFormat() != GL_RGBA32F || levels.isArray() || levels.width() != base.x ||
      levels.height() != base.y || levels.levels() != mips)
    throw std::invalid_argument("buildMinMax: the levels must be an RGBA32F 2D texture of " +
                                std::to_string(base.x) + "x" + std::to_string(base.y) +
                                " with " + std::to_string(mips) +
                                " mip levels (minmaxBaseSize, minmaxMipLevels)");
  const int top = minmaxTopLevel(width, height);
  if (top == 0) {  // a 1 x 1 map: level 0 alone, the layers; the one texel is never read
    const float zeros[4] = {0, 0, 0, 0};
    glClearTexImage(levels.id(), 0, GL_RGBA, GL_FLOAT, zeros);
    return;
  }
  // Level 1 from the layers, then level n from level n-1: each drawn over the whole of a
  // view of its mip level (padding included), reading the view of the level below.
  std::vector<GlTexture> views;
  views.reserve(size_t(top));
  for (int mip = 0; mip < top; ++mip) views.push_back(GlTexture::levelView(levels, mip));
  glBindTextureUnit(MINMAX_NEAR_UNIT, nearLayer.id());
  glBindTextureUnit(MINMAX_FAR_UNIT, farLayer.id());
  for (int level = 1; level <= top; ++level) {
    const char* fromLayers = level == 1 ? "1" : "0";
    levelPrograms_[std::string("#define MINMAX_FROM_LAYERS ") + fromLayers + "\n"].use();
    // Uniforms are per program: set for each level.
    glUniform2i(MINMAX_SIZE_LOCATION, width, height);
    glUniform1i(MINMAX_LEVEL_LOCATION, level);
    glBindTextureUnit(MINMAX_FINER_UNIT, level == 1 ? 0 : views[size_t(level - 2)].id());
    screen_.draw(views[size_t(level - 1)]);
  }
  glBindTextureUnit(MINMAX_FINER_UNIT, 0);
  // Framebuffer writes only: later commands (the next level's fetches, the readers) see them
  // without a memory barrier. The views go; the storage stays with `levels`.
}

void buildMinMax(const GlTexture& nearLayer, const GlTexture& farLayer, GlTexture& levels) {
  static MinMaxBuilder* builder = new MinMaxBuilder;  // never deleted: see the header
  builder->build(nearLayer, farLayer, levels);
}

GlTexture buildMinMaxLevels(const GlTexture& nearLayer, const GlTexture& farLayer) {
  const glm::ivec2 base = minmaxBaseSize(nearLayer.width(), nearLayer.height());
  GlTexture levels(GL_RGBA32F, base.x, base.y, 0,
                   minmaxMipLevels(nearLayer.width(), nearLayer.height()));
  buildMinMax(nearLayer, farLayer, levels);
  return levels;
}

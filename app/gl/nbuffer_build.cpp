#include "gl/nbuffer_build.h"

#include "gl/gpu_layout.h"
#include "shared/nbuffer_layout.h"

static_assert(gpu::distinctBelow({NBUFFER_NEAR_UNIT, NBUFFER_FAR_UNIT}, gpu::kTextureUnits));
static_assert(NBUFFER_FINER_IMAGE < gpu::kImageUnits);

#include <algorithm>
#include <stdexcept>
#include <string>

int nbufferLevelCount(int width, int height) {
  const int size = std::max(width, height);
  int levels = 1;  // level n covers 2^n texels per axis; stop once that spans the map
  while ((1 << (levels - 1)) < size) ++levels;
  return levels;
}

TexelSpan nbufferDistinctTexels(int level, int size) {
  const int span = 1 << level, half = level == 0 ? 0 : span / 2;
  // Windows start at 0 .. max(size - 2^n, 0); the one starting at lo sits at texel lo + a_n
  // (on an axis shorter than 2^n, the single window at the last texel or before).
  const int first = std::min(half, size - 1);
  return {first, std::min(half + std::max(size - span, 0), size - 1) - first + 1};
}

void NBufferBuilder::build(const GlTexture& nearLayer, const GlTexture& farLayer,
                           GlTexture& levels, NBufferTexels texels) {
  const int width = nearLayer.width(), height = nearLayer.height();
  const int count = nbufferLevelCount(width, height);
  if (width < 1 || height < 1 || farLayer.width() != width || farLayer.height() != height ||
      nearLayer.isArray() || farLayer.isArray())
    throw std::invalid_argument("buildNBuffer: near and far layers must be 2D textures of "
                                "the same size >= 1x1");
  if (levels.internalFormat() != GL_RGBA32F || levels.width() != width ||
      levels.height() != height || levels.layers() != count)
    throw std::invalid_argument("buildNBuffer: levels must be an RGBA32F array of " +
                                std::to_string(width) + "x" + std::to_string(height) + "x" +
                                std::to_string(count) + " (nbufferLevelCount)");
  // Levels 0, (near, near, far, 0), and 1 from the layers, into two layers of the array.
  levels01_.use();
  glBindTextureUnit(NBUFFER_NEAR_UNIT, nearLayer.id());
  glBindTextureUnit(NBUFFER_FAR_UNIT, farLayer.id());
  screen_.drawLayers(levels, count > 1 ? std::vector<int>{0, 1} : std::vector<int>{0});

  // Level n from level n-1, read as a single-layer image of the same texture. The texture
  // barrier makes the previous draw's writes visible to this one's reads.
  level_.use();
  for (int level = 2; level < count; ++level) {
    glTextureBarrier();
    glBindImageTexture(NBUFFER_FINER_IMAGE, levels.id(), 0, GL_FALSE, level - 1, GL_READ_ONLY,
                       GL_RGBA32F);
    glUniform1i(NBUFFER_LEVEL_LOCATION, level);
    if (texels == NBufferTexels::All) {
      screen_.draw(levels, level);
    } else {
      const TexelSpan x = nbufferDistinctTexels(level, width);
      const TexelSpan y = nbufferDistinctTexels(level, height);
      screen_.drawRect(levels, level, {x.first, y.first}, {x.count, y.count});
    }
  }
  // Framebuffer writes only: later commands see them without a memory barrier.
}

void buildNBuffer(const GlTexture& nearLayer, const GlTexture& farLayer, GlTexture& levels) {
  static NBufferBuilder* builder = new NBufferBuilder;  // never deleted: see the header
  builder->build(nearLayer, farLayer, levels);
}

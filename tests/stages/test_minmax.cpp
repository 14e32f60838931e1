// Oracle for the min-max mipmap (layout in shaders/shared/minmax.glsl;
// docs/decisions/024-minmax-mipmap-levels.md): every texel of every level equals the brute-force
// min/max over its aligned cell of level-0 texels, computed on the CPU from the cell definition
// alone (never from the 2 x 2 recurrence the shader uses), read back from mip level n - 1 of the
// texture, and the padding past each level's cells is 0 (level 0 is the layers, not stored; the
// trace oracle tests read it through the search).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "shared_inputs/minmax/minmax_build.h"
#include "scene/scene_builtin.h"
#include "support/gl_test.h"
#include "support/random_layers.h"

namespace {

void checkEveryTexel(int width, int height, unsigned seed) {
  headlessContext();
  const Layers layers = randomLayers(width, height, seed);
  const GlTexture nearLayer = uploadDepth(layers.nearDepth, width, height);
  const GlTexture farLayer = uploadDepth(layers.farDepth, width, height);
  const GlTexture levels = buildMinMaxLevels(nearLayer, farLayer);
  const int top = minmaxTopLevel(width, height);
  ASSERT_GE(1 << top, std::max(width, height));
  ASSERT_EQ(levels.levels(), std::max(top, 1));
  for (int level = 1; level <= top; ++level) {
    const int span = 1 << level, mip = level - 1;
    const std::vector<float> texels = levels.readLevelFloats(mip);
    const int stride = levels.levelWidth(mip);
    const glm::ivec2 size = minmaxLevelSize(level, width, height);
    ASSERT_LE(size.x, levels.levelWidth(mip)) << "level " << level;
    ASSERT_LE(size.y, levels.levelHeight(mip)) << "level " << level;
    if (level == top) {
      ASSERT_EQ(size, glm::ivec2(1, 1));
    }
    for (int cy = 0; cy < levels.levelHeight(mip); ++cy)
      for (int cx = 0; cx < stride; ++cx) {
        const size_t at = (size_t(cy) * stride + cx) * 4;
        if (cx >= size.x || cy >= size.y) {  // padding: no cell there
          for (int c = 0; c < 4; ++c)
            ASSERT_EQ(texels[at + c], 0.0f) << "level " << level << " padding " << cx << "," << cy;
          continue;
        }
        float nearMin = 1e30f, nearMax = -1e30f, farMax = -1e30f;
        for (int y = cy * span; y < std::min((cy + 1) * span, height); ++y)
          for (int x = cx * span; x < std::min((cx + 1) * span, width); ++x) {
            nearMin = std::min(nearMin, layers.nearDepth[size_t(y) * width + x]);
            nearMax = std::max(nearMax, layers.nearDepth[size_t(y) * width + x]);
            farMax = std::max(farMax, layers.farDepth[size_t(y) * width + x]);
          }
        ASSERT_EQ(texels[at + 0], nearMin) << "level " << level << " cell " << cx << "," << cy;
        ASSERT_EQ(texels[at + 1], nearMax) << "level " << level << " cell " << cx << "," << cy;
        ASSERT_EQ(texels[at + 2], farMax) << "level " << level << " cell " << cx << "," << cy;
        ASSERT_EQ(texels[at + 3], 0.0f);
      }
  }
}

}  // namespace

// The stored levels hold 1/3 of one level at a power-of-two map, and under 4/3 of one level
// (the padding) at any map, instead of the N-buffer's log2(W) + 1 levels.
TEST(MinMax, MipLevelsAreSmall) {
  for (glm::ivec2 map : {glm::ivec2(1, 1), {1, 7}, {5, 3}, {100, 37}, {300, 300}, {256, 256},
                         {2048, 2048}}) {
    const glm::ivec2 base = minmaxBaseSize(map.x, map.y);
    double stored = 0;
    for (int mip = 0; mip < minmaxMipLevels(map.x, map.y); ++mip)
      stored += double(std::max(1, base.x >> mip)) * std::max(1, base.y >> mip);
    const double levelTexels = double(map.x) * map.y;
    EXPECT_LE(stored, 4.0 / 3.0 * levelTexels + 2 * (map.x + map.y) + 16) << map.x;
    if (map.x == 256 || map.x == 2048) {
      EXPECT_LE(stored, levelTexels / 3.0) << map.x;
    }
  }
}

TEST(MinMax, EveryTexelOfEveryLevelEqualsBruteForceSmallSizes) {
  for (int size : {1, 2, 3, 5, 8, 13}) checkEveryTexel(size, size, unsigned(size));
}
TEST(MinMax, EveryTexelOfEveryLevelEqualsBruteForceNonSquare) {
  checkEveryTexel(37, 100, 3);
  checkEveryTexel(100, 37, 4);
  checkEveryTexel(1, 9, 5);
}
TEST(MinMax, EveryTexelOfEveryLevelEqualsBruteForce512) { checkEveryTexel(512, 512, 6); }

TEST(MinMax, RejectsLevelsOfTheWrongShape) {
  headlessContext();
  const GlTexture nearLayer(GL_DEPTH_COMPONENT32F, 16, 16), farLayer(GL_DEPTH_COMPONENT32F, 16, 16);
  GlTexture wrongSize(GL_RGBA32F, 16, 16, 0, 4), oneLevel(GL_RGBA32F, 8, 8);
  EXPECT_THROW(buildMinMax(nearLayer, farLayer, wrongSize), std::invalid_argument);
  EXPECT_THROW(buildMinMax(nearLayer, farLayer, oneLevel), std::invalid_argument);
}

// In the pipeline: built from the frame's light layers; the top texel bounds the whole map.
TEST(MinMaxStage, BuiltFromTheLightLayersOfTheFrame) {
  PipelineRun run(makeBuiltinScene("cube"), {"light.resolution=128", "trace.hierarchy=minmax"},
                  64, 64);
  const GlTexture& levels = run.frame->texture("minmax.levels");
  EXPECT_EQ(glm::ivec2(levels.width(), levels.height()), glm::ivec2(64, 64));
  EXPECT_EQ(levels.levels(), 7);  // levels 1 .. 7: 64^2 .. 1
  EXPECT_EQ(run.frame->counters.at("minmax.levels"), 8.0);
  const auto nearLayer = run.read("light_layers.near");
  const auto farLayer = run.read("light_layers.far");
  const auto texels = levels.readLevelFloats(6);  // level 7, one texel
  ASSERT_EQ(texels.size(), 4u);
  const size_t at = 0;
  EXPECT_LT(*std::min_element(nearLayer.begin(), nearLayer.end()), 1.0f);  // the cube is in the map
  EXPECT_EQ(texels[at + 0], *std::min_element(nearLayer.begin(), nearLayer.end()));
  EXPECT_EQ(texels[at + 1], *std::max_element(nearLayer.begin(), nearLayer.end()));
  EXPECT_EQ(texels[at + 2], *std::max_element(farLayer.begin(), farLayer.end()));
}

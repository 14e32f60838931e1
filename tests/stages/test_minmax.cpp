// Oracle for the min-max mipmap (layout in shaders/shared/minmax.glsl;
// docs/decisions/024-minmax-mipmap-atlas.md): every texel of every level equals the brute-force
// min/max over its aligned cell of level-0 texels, computed on the CPU from the cell definition
// alone (never from the 2 x 2 recurrence the shader uses), and the atlas places the levels >= 1
// where the layout says (level 0 is the layers, not stored; the trace oracle tests read it through
// the search).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "gl/minmax_build.h"
#include "scene/scene_builtin.h"
#include "support/gl_test.h"
#include "support/random_layers.h"

namespace {

void checkEveryTexel(int width, int height, unsigned seed) {
  headlessContext();
  const Layers layers = randomLayers(width, height, seed);
  const GlTexture nearLayer = uploadDepth(layers.nearDepth, width, height);
  const GlTexture farLayer = uploadDepth(layers.farDepth, width, height);
  const glm::ivec2 atlasSize = minmaxAtlasSize(width, height);
  GlTexture atlas(GL_RGBA32F, atlasSize.x, atlasSize.y);
  buildMinMax(nearLayer, farLayer, atlas);
  const std::vector<float> texels = atlas.readFloats();
  const int top = minmaxTopLevel(width, height);
  ASSERT_GE(1 << top, std::max(width, height));
  std::vector<bool> covered(size_t(atlasSize.x) * atlasSize.y, false);
  for (int level = 1; level <= top; ++level) {
    const int span = 1 << level;
    const glm::ivec2 size = minmaxLevelSize(level, width, height), origin =
        minmaxLevelOrigin(level, width, height);
    ASSERT_LE(origin.x + size.x, atlasSize.x);
    ASSERT_LE(origin.y + size.y, atlasSize.y);
    if (level == top) {
      ASSERT_EQ(size, glm::ivec2(1, 1));
    }
    for (int cy = 0; cy < size.y; ++cy)
      for (int cx = 0; cx < size.x; ++cx) {
        float nearMin = 1e30f, nearMax = -1e30f, farMax = -1e30f;
        for (int y = cy * span; y < std::min((cy + 1) * span, height); ++y)
          for (int x = cx * span; x < std::min((cx + 1) * span, width); ++x) {
            nearMin = std::min(nearMin, layers.nearDepth[size_t(y) * width + x]);
            nearMax = std::max(nearMax, layers.nearDepth[size_t(y) * width + x]);
            farMax = std::max(farMax, layers.farDepth[size_t(y) * width + x]);
          }
        const size_t at = (size_t(origin.y + cy) * atlasSize.x + origin.x + cx) * 4;
        ASSERT_FALSE(covered[at / 4]) << "levels overlap at level " << level;
        covered[at / 4] = true;
        ASSERT_EQ(texels[at + 0], nearMin) << "level " << level << " cell " << cx << "," << cy;
        ASSERT_EQ(texels[at + 1], nearMax) << "level " << level << " cell " << cx << "," << cy;
        ASSERT_EQ(texels[at + 2], farMax) << "level " << level << " cell " << cx << "," << cy;
      }
  }
  // The rest of the atlas is cleared (no stale or uninitialized values in the view).
  for (size_t i = 0; i < covered.size(); ++i)
    if (!covered[i]) {
      for (int c = 0; c < 4; ++c) ASSERT_EQ(texels[i * 4 + c], 0.0f) << "atlas texel " << i;
    }
}

}  // namespace

// The levels never overlap in the atlas, and the atlas holds 1/3 of one level (plus the
// padding right of levels >= 2) instead of the N-buffer's log2(W) + 1 levels.
TEST(MinMax, AtlasLayoutLevelsAreDisjointAndSmall) {
  for (glm::ivec2 map : {glm::ivec2(1, 1), {1, 7}, {5, 3}, {100, 37}, {256, 256}, {2048, 2048}}) {
    const glm::ivec2 atlas = minmaxAtlasSize(map.x, map.y);
    long used = 0;
    for (int level = 1; level <= minmaxTopLevel(map.x, map.y); ++level) {
      const glm::ivec2 size = minmaxLevelSize(level, map.x, map.y);
      used += long(size.x) * size.y;
      const glm::ivec2 origin = minmaxLevelOrigin(level, map.x, map.y);
      EXPECT_EQ(origin.x, 0);
      EXPECT_LE(size.x, atlas.x);
      // stacked right below the previous level
      const int below = level == 1 ? 0 : minmaxLevelOrigin(level - 1, map.x, map.y).y +
                                             minmaxLevelSize(level - 1, map.x, map.y).y;
      EXPECT_EQ(origin.y, below);
      EXPECT_LE(origin.y + size.y, atlas.y);
    }
    const double levelTexels = double(map.x) * map.y;
    EXPECT_LE(double(used), 1.0 / 3.0 * levelTexels + 2 * (map.x + map.y) + 16) << map.x;
    if (map.x >= 256) {
      EXPECT_LE(double(atlas.x) * atlas.y, 0.5 * levelTexels) << map.x;
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

TEST(MinMax, RejectsAnAtlasOfTheWrongShape) {
  headlessContext();
  const GlTexture nearLayer(GL_DEPTH_COMPONENT32F, 16, 16), farLayer(GL_DEPTH_COMPONENT32F, 16, 16);
  GlTexture wrong(GL_RGBA32F, 16, 16);
  EXPECT_THROW(buildMinMax(nearLayer, farLayer, wrong), std::invalid_argument);
}

// In the pipeline: built from the frame's light layers; the top texel bounds the whole map.
TEST(MinMaxStage, BuiltFromTheLightLayersOfTheFrame) {
  PipelineRun run(makeBuiltinScene("cube"), {"light.resolution=128", "trace.hierarchy=minmax"},
                  64, 64);
  const GlTexture& atlas = run.frame->texture("minmax.levels");
  EXPECT_EQ(glm::ivec2(atlas.width(), atlas.height()), minmaxAtlasSize(128, 128));
  EXPECT_EQ(run.frame->counters.at("minmax.levels"), 8.0);
  const auto nearLayer = run.read("light_layers.near");
  const auto farLayer = run.read("light_layers.far");
  const auto texels = atlas.readFloats();
  const glm::ivec2 top = minmaxLevelOrigin(7, 128, 128);
  const size_t at = (size_t(top.y) * atlas.width() + top.x) * 4;
  EXPECT_LT(*std::min_element(nearLayer.begin(), nearLayer.end()), 1.0f);  // the cube is in the map
  EXPECT_EQ(texels[at + 0], *std::min_element(nearLayer.begin(), nearLayer.end()));
  EXPECT_EQ(texels[at + 1], *std::max_element(nearLayer.begin(), nearLayer.end()));
  EXPECT_EQ(texels[at + 2], *std::max_element(farLayer.begin(), farLayer.end()));
}

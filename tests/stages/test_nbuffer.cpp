// Oracle for the N-buffer (thesis §3.5; layout in shaders/shared/nbuffer.glsl): every texel
// of every level equals the brute-force min/max over its window, computed on the CPU from
// the window definition alone (never from the 4-fetch recurrence the shader uses).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "gl/nbuffer_build.h"
#include "scene/scene_builtin.h"
#include "support/gl_test.h"
#include "support/random_layers.h"

namespace {

// The window of level `level` texel `x` on an axis of `size` texels, straight from the
// comment in nbuffer.glsl: lo = clamp(x - a_n, 0, max(size - 2^n, 0)), a_n = 2^n / 2.
std::pair<int, int> window1D(int level, int x, int size) {
  const int span = 1 << level, centerOffset = span / 2;
  const int lo = std::clamp(x - centerOffset, 0, std::max(size - span, 0));
  return {lo, std::min(lo + span, size) - 1};
}

// Brute-force min/max over every texel's window. The window is a rectangle, so it is done
// separably (min over a rectangle = min over its rows of the min within each row), which
// visits every texel of every window once per axis and keeps 512^2 x 10 levels at ~1 s.
std::vector<float> bruteForceLevel(const Layers& layers, int level) {
  const int w = layers.width, h = layers.height;
  std::vector<float> rows(size_t(w) * h * 3);  // per texel: min near, max near, max far
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const auto [lo, hi] = window1D(level, x, w);
      float nearMin = 2, nearMax = -1, farMax = -1;
      for (int xs = lo; xs <= hi; ++xs) {
        const size_t i = size_t(y) * w + xs;
        nearMin = std::min(nearMin, layers.nearDepth[i]);
        nearMax = std::max(nearMax, layers.nearDepth[i]);
        farMax = std::max(farMax, layers.farDepth[i]);
      }
      float* out = &rows[(size_t(y) * w + x) * 3];
      out[0] = nearMin, out[1] = nearMax, out[2] = farMax;
    }
  std::vector<float> result(size_t(w) * h * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const auto [lo, hi] = window1D(level, y, h);
      float nearMin = 2, nearMax = -1, farMax = -1;
      for (int ys = lo; ys <= hi; ++ys) {
        const float* row = &rows[(size_t(ys) * w + x) * 3];
        nearMin = std::min(nearMin, row[0]);
        nearMax = std::max(nearMax, row[1]);
        farMax = std::max(farMax, row[2]);
      }
      float* out = &result[(size_t(y) * w + x) * 4];
      out[0] = nearMin, out[1] = nearMax, out[2] = farMax, out[3] = 0;
    }
  return result;
}

void checkEveryTexel(int width, int height) {
  headlessContext();
  const Layers layers = randomLayers(width, height, unsigned(width * 7919 + height));
  const GlTexture nearLayer = uploadDepth(layers.nearDepth, width, height);
  const GlTexture farLayer = uploadDepth(layers.farDepth, width, height);
  // The oracle's input must be what the GPU holds (DEPTH_COMPONENT32F keeps [0,1] floats).
  ASSERT_EQ(nearLayer.readFloats(), layers.nearDepth);
  ASSERT_EQ(farLayer.readFloats(), layers.farDepth);

  const int count = nbufferLevelCount(width, height);
  GlTexture levels(GL_RGBA32F, width, height, count);
  buildNBuffer(nearLayer, farLayer, levels);
  for (int level = 0; level < count; ++level) {
    const std::vector<float> gpu = levels.readFloats(level);
    const std::vector<float> expected = bruteForceLevel(layers, level);
    ASSERT_EQ(gpu.size(), expected.size());
    size_t mismatches = 0;
    for (size_t i = 0; i < gpu.size(); ++i)
      if (gpu[i] != expected[i] && ++mismatches <= 5) {
        const size_t texel = i / 4;
        ADD_FAILURE() << width << "x" << height << " level " << level << " texel ("
                      << texel % width << ", " << texel / width << ") channel " << i % 4
                      << ": gpu " << gpu[i] << ", brute force " << expected[i];
      }
    EXPECT_EQ(mismatches, 0u) << width << "x" << height << " level " << level;
  }
}

}  // namespace

TEST(NBuffer, LevelCountCoversTheMapWithTheCoarsestWindow) {
  EXPECT_EQ(nbufferLevelCount(1, 1), 1);
  EXPECT_EQ(nbufferLevelCount(2, 2), 2);
  EXPECT_EQ(nbufferLevelCount(3, 3), 3);
  EXPECT_EQ(nbufferLevelCount(100, 37), 8);
  EXPECT_EQ(nbufferLevelCount(512, 512), 10);
  EXPECT_EQ(nbufferLevelCount(513, 1), 11);
  // The coarsest window spans the whole map from every texel.
  for (int size : {1, 2, 3, 37, 100, 512, 513}) {
    const int top = nbufferLevelCount(size, 1) - 1;
    for (int x = 0; x < size; ++x) ASSERT_EQ(window1D(top, x, size), std::make_pair(0, size - 1));
  }
}

TEST(NBuffer, EveryTexelOfEveryLevelEqualsBruteForceSmallSizes) {
  for (int size : {1, 2, 3, 5, 64, 100}) checkEveryTexel(size, size);
}

TEST(NBuffer, EveryTexelOfEveryLevelEqualsBruteForceNonSquare) {
  checkEveryTexel(100, 37);
  checkEveryTexel(37, 100);
  checkEveryTexel(7, 1);
  checkEveryTexel(1, 6);
}

TEST(NBuffer, EveryTexelOfEveryLevelEqualsBruteForce256) { checkEveryTexel(256, 256); }

TEST(NBuffer, EveryTexelOfEveryLevelEqualsBruteForce512) { checkEveryTexel(512, 512); }

TEST(NBuffer, RejectsLevelsOfTheWrongShape) {
  headlessContext();
  GlTexture nearLayer(GL_DEPTH_COMPONENT32F, 16, 16), farLayer(GL_DEPTH_COMPONENT32F, 16, 16);
  GlTexture tooFew(GL_RGBA32F, 16, 16, 4);
  EXPECT_THROW(buildNBuffer(nearLayer, farLayer, tooFew), std::invalid_argument);
  GlTexture otherSize(GL_RGBA32F, 8, 16, 5);
  EXPECT_THROW(buildNBuffer(nearLayer, farLayer, otherSize), std::invalid_argument);
}

// The stage builds from this frame's light layers: level 0 is (near, near, far, 0) and the
// coarsest level holds the whole-map bounds at every texel.
TEST(NBufferStage, BuiltFromTheLightLayersOfTheFrame) {
  PipelineRun run(makeBuiltinScene("cube"), {"light.resolution=128"}, 64, 64);
  const GlTexture& levels = run.frame->texture("nbuffer.levels");
  ASSERT_EQ(levels.layers(), 8);
  EXPECT_EQ(run.frame->counters.at("nbuffer.levels"), 8.0);
  const auto nearLayer = run.read("light_layers.near");
  const auto farLayer = run.read("light_layers.far");
  const auto level0 = levels.readFloats(0);
  const auto top = levels.readFloats(7);
  const float nearMin = *std::min_element(nearLayer.begin(), nearLayer.end());
  const float nearMax = *std::max_element(nearLayer.begin(), nearLayer.end());
  const float farMax = *std::max_element(farLayer.begin(), farLayer.end());
  EXPECT_LT(nearMin, 1.0f);  // the cube is in the map
  for (size_t i = 0; i < nearLayer.size(); ++i) {
    ASSERT_EQ(level0[i * 4 + 0], nearLayer[i]);
    ASSERT_EQ(level0[i * 4 + 1], nearLayer[i]);
    ASSERT_EQ(level0[i * 4 + 2], farLayer[i]);
    ASSERT_EQ(level0[i * 4 + 3], 0.0f);
    ASSERT_EQ(top[i * 4 + 0], nearMin);
    ASSERT_EQ(top[i * 4 + 1], nearMax);
    ASSERT_EQ(top[i * 4 + 2], farMax);
  }
}

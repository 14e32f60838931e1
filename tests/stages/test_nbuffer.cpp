// Oracle for the N-buffer (thesis §3.5; layout in shaders/shared/nbuffer.glsl): every texel
// of every level equals the brute-force min/max over its window, computed on the CPU from
// the window definition alone (never from the 4-fetch recurrence the shader uses).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

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

// The texel a search reads for the level-`level` window starting at `lo`, also from the
// comment in nbuffer.glsl: lo + a_n, lo clamped like the window, kept inside the map.
int texelForWindow(int level, int lo, int size) {
  const int span = 1 << level;
  return std::min(std::clamp(lo, 0, std::max(size - span, 0)) + span / 2, size - 1);
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

// Distinct mode writes the texels holding distinct windows and leaves the others as they
// were: cleared to a sentinel first, the band texels keep it, the rest equal brute force.
// Levels 0 and 1 are one pass over every texel (nbuffer_levels01.frag): all equal brute force.
void checkDistinctTexels(int width, int height) {
  headlessContext();
  const Layers layers = randomLayers(width, height, unsigned(width * 31 + height));
  const GlTexture nearLayer = uploadDepth(layers.nearDepth, width, height);
  const GlTexture farLayer = uploadDepth(layers.farDepth, width, height);
  const int count = nbufferLevelCount(width, height);
  GlTexture levels(GL_RGBA32F, width, height, count);
  const float sentinel[4] = {-7, -7, -7, -7};
  glClearTexImage(levels.id(), 0, GL_RGBA, GL_FLOAT, sentinel);
  NBufferBuilder builder;
  builder.build(nearLayer, farLayer, levels, NBufferTexels::Distinct);
  size_t written = 0, skipped = 0;
  for (int level = 0; level < count; ++level) {
    const std::vector<float> gpu = levels.readFloats(level);
    const std::vector<float> expected = bruteForceLevel(layers, level);
    const TexelSpan xs = nbufferDistinctTexels(level, width);
    const TexelSpan ys = nbufferDistinctTexels(level, height);
    size_t mismatches = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const bool distinct = level <= 1 || (x >= xs.first && x < xs.first + xs.count &&
                                             y >= ys.first && y < ys.first + ys.count);
        (distinct ? written : skipped) += 1;
        for (int c = 0; c < 4; ++c) {
          const size_t i = (size_t(y) * width + x) * 4 + c;
          const float want = distinct ? expected[i] : sentinel[c];
          if (gpu[i] != want && ++mismatches <= 5)
            ADD_FAILURE() << width << "x" << height << " level " << level << " texel (" << x
                          << ", " << y << ") channel " << c << ": gpu " << gpu[i] << ", want "
                          << want << (distinct ? " (brute force)" : " (not written)");
        }
      }
    EXPECT_EQ(mismatches, 0u) << width << "x" << height << " level " << level;
  }
  if (width >= 4 && height >= 4) {
    EXPECT_GT(skipped, 0u) << "nothing skipped";
  }
  EXPECT_GT(written, 0u);
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

// The distinct span is exactly the set of texels searches read (texelForWindow over every
// window start), and it holds every window of the level once.
TEST(NBuffer, DistinctTexelsAreTheTexelsSearchesRead) {
  for (int size : {1, 2, 3, 5, 7, 37, 64, 100, 512, 513}) {
    for (int level = 0; level < nbufferLevelCount(size, 1); ++level) {
      std::set<int> read;
      for (int lo = 0; lo < size; ++lo) read.insert(texelForWindow(level, lo, size));
      const TexelSpan span = nbufferDistinctTexels(level, size);
      ASSERT_EQ(int(read.size()), span.count) << "size " << size << " level " << level;
      EXPECT_EQ(*read.begin(), span.first) << "size " << size << " level " << level;
      EXPECT_EQ(*read.rbegin(), span.first + span.count - 1)
          << "size " << size << " level " << level;
      std::set<std::pair<int, int>> spanWindows, allWindows;
      for (int x = span.first; x < span.first + span.count; ++x)
        spanWindows.insert(window1D(level, x, size));
      for (int x = 0; x < size; ++x) allWindows.insert(window1D(level, x, size));
      EXPECT_EQ(int(spanWindows.size()), span.count) << "a window twice, size " << size;
      EXPECT_EQ(spanWindows, allWindows) << "a window missing, size " << size << " level " << level;
    }
  }
}

TEST(NBuffer, DistinctTexelsEqualBruteForceAndTheRestStayUnwritten) {
  for (int size : {1, 2, 3, 5, 64, 100}) checkDistinctTexels(size, size);
  checkDistinctTexels(100, 37);
  checkDistinctTexels(7, 1);
  checkDistinctTexels(1, 6);
  checkDistinctTexels(512, 512);
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

// Demand: a run that asks only for the composite writes the distinct texels alone, marks the
// levels partial (not shown, not exported) and gives the same images to the last bit as a run
// that asks for everything: deferred (classification, trace) and forward (the top level's
// bounds), one to three layers, a map whose size is no power of two.
TEST(NBufferStage, LevelsNotAskedForArePartialAndChangeNoResult) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"cube", {"light.resolution=128", "light.layers=two"}},
      {"spheres", {"light.resolution=200", "light.layers=one"}},
      {"cube", {"light.resolution=200", "light.layers=three"}},
      {"spheres", {"light.resolution=128", "trace.deferred=false"}},
  };
  for (const auto& [scene, sets] : cases) {
    std::vector<std::string> all = {"trace.search=hierarchical", "trace.hierarchy=nbuffer",
                                    "trace.rays=2"};
    all.insert(all.end(), sets.begin(), sets.end());
    PipelineRun run(makeBuiltinScene(scene), all, 96, 72);
    const auto everything = run.read("composite.color");
    const auto visibility = run.read("trace.visibility");
    EXPECT_TRUE(run.frame->has("nbuffer.levels"));
    // The texture is reused: a sentinel in it makes any read of a texel not written show.
    const float sentinel[4] = {-7, -7, -7, -7};
    glClearTexImage(run.frame->textures.at("nbuffer.levels").id(), 0, GL_RGBA, GL_FLOAT, sentinel);
    run.pipeline->run(*run.frame, {"composite.color"});
    EXPECT_FALSE(run.frame->has("nbuffer.levels")) << scene << " " << sets[0];
    EXPECT_THROW(run.frame->texture("nbuffer.levels"), std::runtime_error);
    EXPECT_EQ(run.read("composite.color"), everything) << scene << " " << sets[0] << " " << sets[1];
    EXPECT_EQ(run.read("trace.visibility"), visibility)
        << scene << " " << sets[0] << " " << sets[1];
    run.pipeline->run(*run.frame, {"composite.color", "nbuffer.levels"});
    EXPECT_TRUE(run.frame->has("nbuffer.levels"));
  }
}

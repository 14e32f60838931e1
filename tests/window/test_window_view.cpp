// The window's texture view on llvmpipe: the GPU mapping (shaders/view/view.comp) shows exactly
// the bytes the CPU twin (displayRgb8ForView over app/io/colormap.cpp) writes into "PNG as
// displayed", for every colormap, channel selection, overlay, array layer and integer
// texture; texel read-back returns what was uploaded; the difference view (A - B) equals the
// CPU's subtraction.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "io/colormap.h"
#include "support/gl_test.h"
#include "window/views/texture_view.h"
#include "window/views/ui_view_difference.h"
#include "window/views/ui_view_settings.h"

namespace {

constexpr int kWidth = 37, kHeight = 23;  // not multiples of 8: partial groups

// Values spanning the range, outside it, and the broken ones the overlay must catch.
std::vector<float> testValues(int channels, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> value(-0.5f, 1.5f);
  std::vector<float> values(size_t(kWidth) * kHeight * channels);
  for (float& v : values) v = value(random);
  values[3] = std::numeric_limits<float>::quiet_NaN();
  values[channels * 5] = std::numeric_limits<float>::infinity();
  values[channels * 7] = -std::numeric_limits<float>::infinity();
  values[channels * 9] = 0.5f;  // an exact tie for the byte rounding
  return values;
}

GlTexture upload(GLenum format, const std::vector<float>& values, int channels, int layers = 0) {
  GlTexture texture(format, kWidth, kHeight, layers);
  const GLenum pixelFormat = channels == 4 ? GL_RGBA : GL_RED;
  if (layers > 0)
    glTextureSubImage3D(texture.id(), 0, 0, 0, 0, kWidth, kHeight, layers, pixelFormat,
                        GL_FLOAT, values.data());
  else
    glTextureSubImage2D(texture.id(), 0, 0, 0, kWidth, kHeight, pixelFormat, GL_FLOAT,
                        values.data());
  return texture;
}

// The display texture as top-row-first RGB bytes (the PNG's order).
std::vector<std::uint8_t> displayedBytes(const GlTexture& display) {
  std::vector<std::uint8_t> rgba(size_t(display.width()) * display.height() * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(display.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(rgba.size()), rgba.data());
  std::vector<std::uint8_t> rgb(size_t(display.width()) * display.height() * 3);
  for (int y = 0; y < display.height(); ++y)
    for (int x = 0; x < display.width(); ++x)
      for (int c = 0; c < 3; ++c)
        rgb[(size_t(y) * display.width() + x) * 3 + c] =
            rgba[(size_t(display.height() - 1 - y) * display.width() + x) * 4 + c];
  return rgb;
}

void expectSameBytes(const std::vector<std::uint8_t>& gpu, const std::vector<std::uint8_t>& cpu,
                     const std::string& what) {
  ASSERT_EQ(gpu.size(), cpu.size()) << what;
  int differing = 0;
  for (size_t i = 0; i < gpu.size(); ++i)
    if (gpu[i] != cpu[i] && ++differing <= 3)
      ADD_FAILURE() << what << ": byte " << i << " (texel " << i / 3 << ") GPU "
                    << int(gpu[i]) << " CPU " << int(cpu[i]);
  EXPECT_EQ(differing, 0) << what;
}

}  // namespace

TEST(WindowView, GpuMappingEqualsCpuTwinForEveryColormapAndChannel) {
  headlessContext();
  const std::vector<float> values = testValues(4, 1);
  GlTexture texture = upload(GL_RGBA32F, values, 4);
  TextureView view;
  for (int map = 0; map < 4; ++map)
    for (int channel = -1; channel < 4; ++channel)
      for (bool overlay : {false, true}) {
        ViewSettings settings;
        settings.colormap = Colormap(map);
        settings.black = -0.25f;
        settings.white = 1.25f;
        settings.overlay = overlay;
        for (int c = 0; c < 4; ++c)
          settings.channels[size_t(c)] = channel < 0 ? c < 3 : c == channel;
        const std::string what = std::string(colormapName(Colormap(map))) + " channel " +
                                 std::to_string(channel) + (overlay ? " overlay" : "");
        expectSameBytes(displayedBytes(view.render(texture, settings)),
                        displayRgb8ForView(values, kWidth, kHeight, 4, settings), what);
      }
}

TEST(WindowView, DisabledChannelsAreBlackAndTheOverlayPaintsBrokenValues) {
  headlessContext();
  std::vector<float> values(size_t(kWidth) * kHeight * 4, 0.5f);
  values[0] = std::numeric_limits<float>::quiet_NaN();  // texel 0: R NaN
  values[4 + 1] = std::numeric_limits<float>::infinity();  // texel 1: G Inf
  values[8 + 2] = -1.0f;                                     // texel 2: B negative
  GlTexture texture = upload(GL_RGBA32F, values, 4);
  TextureView view;
  ViewSettings settings;
  settings.channels = {true, false, true, false};  // R and B: G shows 0
  settings.overlay = true;
  const auto bytes = displayedBytes(view.render(texture, settings));
  expectSameBytes(bytes, displayRgb8ForView(values, kWidth, kHeight, 4, settings), "R+B");
  // GL row 0 is the PNG's last row.
  const auto at = [&](int x, int c) { return int(bytes[(size_t(kHeight - 1) * kWidth + x) * 3 + c]); };
  EXPECT_EQ(at(0, 0), 255); EXPECT_EQ(at(0, 1), 0); EXPECT_EQ(at(0, 2), 255);  // NaN magenta
  EXPECT_EQ(at(1, 0), 128); EXPECT_EQ(at(1, 1), 0); EXPECT_EQ(at(1, 2), 128);  // G hidden: no Inf
  EXPECT_EQ(at(2, 0), 0); EXPECT_EQ(at(2, 1), 0); EXPECT_EQ(at(2, 2), 255);    // negative blue
  EXPECT_EQ(at(3, 0), 128); EXPECT_EQ(at(3, 1), 0); EXPECT_EQ(at(3, 2), 128);
}

TEST(WindowView, ArrayLayersIntegerAndDepthTexturesMapLikeTheCpu) {
  headlessContext();
  TextureView view;
  // 1. RGBA32F array (the N-buffer's format): each layer on its own.
  std::vector<float> layered;
  for (unsigned layer = 0; layer < 3; ++layer) {
    const auto one = testValues(4, 10 + layer);
    layered.insert(layered.end(), one.begin(), one.end());
  }
  GlTexture array = upload(GL_RGBA32F, layered, 4, 3);
  for (int layer = 0; layer < 3; ++layer) {
    ViewSettings settings;
    settings.layer = layer;
    settings.channels = {false, true, false, false};
    settings.colormap = Colormap::Perceptual;
    const std::vector<float> values = array.readFloats(layer);
    expectSameBytes(displayedBytes(view.render(array, settings)),
                    displayRgb8ForView(values, kWidth, kHeight, 4, settings),
                    "layer " + std::to_string(layer));
  }
  // 2. R32UI mask through the categorical map.
  std::vector<GLuint> mask(size_t(kWidth) * kHeight);
  for (size_t i = 0; i < mask.size(); ++i) mask[i] = GLuint(i % 11);
  GlTexture integer(GL_R32UI, kWidth, kHeight);
  glTextureSubImage2D(integer.id(), 0, 0, 0, kWidth, kHeight, GL_RED_INTEGER, GL_UNSIGNED_INT,
                      mask.data());
  ViewSettings categorical;
  categorical.channels = {true, false, false, false};
  categorical.colormap = Colormap::Categorical;
  categorical.black = 0;
  categorical.white = 10;
  expectSameBytes(displayedBytes(view.render(integer, categorical)),
                  displayRgb8ForView(integer.readFloats(), kWidth, kHeight, 1, categorical),
                  "R32UI");
  EXPECT_EQ(readTexel(integer, 5, 2)[0], float((2 * kWidth + 5) % 11));
  // 3. Depth, sampled as a plain sampler2D.
  std::vector<float> depth(size_t(kWidth) * kHeight);
  for (size_t i = 0; i < depth.size(); ++i) depth[i] = float(i) / float(depth.size());
  GlTexture depthTexture(GL_DEPTH_COMPONENT32F, kWidth, kHeight);
  glTextureSubImage2D(depthTexture.id(), 0, 0, 0, kWidth, kHeight, GL_DEPTH_COMPONENT, GL_FLOAT,
                      depth.data());
  ViewSettings gray;
  gray.channels = {true, false, false, false};
  expectSameBytes(displayedBytes(view.render(depthTexture, gray)),
                  displayRgb8ForView(depth, kWidth, kHeight, 1, gray), "depth");
}

TEST(WindowView, ReadTexelAndRegionReturnTheUploadedValues) {
  headlessContext();
  const auto layered0 = testValues(4, 20), layered1 = testValues(4, 21);
  std::vector<float> both(layered0);
  both.insert(both.end(), layered1.begin(), layered1.end());
  GlTexture array = upload(GL_RGBA32F, both, 4, 2);
  const int x = 11, y = 17;
  const auto texel = readTexel(array, x, y, 1);
  for (int c = 0; c < 4; ++c) {
    const float expected = layered1[(size_t(y) * kWidth + x) * 4 + size_t(c)];
    if (std::isnan(expected)) EXPECT_TRUE(std::isnan(texel[size_t(c)]));
    else EXPECT_EQ(texel[size_t(c)], expected) << c;
  }
  EXPECT_EQ(readTexel(array, -1, 0)[0], 0.0f);  // outside: zeros, no GL error
  const auto region = readRegion(array, 30, 20, 20, 20, 0);  // clamped to 7 x 3
  ASSERT_EQ(region.size(), size_t(7 * 3 * 4));
  EXPECT_EQ(region[4 * (7 * 2 + 6) + 1], layered0[(size_t(22) * kWidth + 36) * 4 + 1]);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(WindowView, AutofitRangeCoversFiniteShownValuesOnly) {
  std::vector<float> values = {0.5f, -2.0f, 7.0f, 100.0f,
                               std::numeric_limits<float>::quiet_NaN(), 3.0f, -1.0f, 0.0f};
  ViewSettings settings;
  settings.channels = {true, true, false, false};
  float low = 0, high = 0;
  ASSERT_TRUE(finiteRange(values, 4, settings, low, high));
  EXPECT_EQ(low, -2.0f);
  EXPECT_EQ(high, 3.0f);
  settings.channels = {false, false, false, true};  // alpha alone
  ASSERT_TRUE(finiteRange(values, 4, settings, low, high));
  EXPECT_EQ(low, 0.0f);
  EXPECT_EQ(high, 100.0f);
}

namespace {
// Equal bit for bit, or both NaN.
void expectSameFloats(const std::vector<float>& gpu, const std::vector<float>& cpu, const std::string& what) {
  ASSERT_EQ(gpu.size(), cpu.size()) << what;
  int differing = 0;
  for (size_t i = 0; i < gpu.size(); ++i) {
    const bool same = std::isnan(cpu[i]) ? std::isnan(gpu[i]) : gpu[i] == cpu[i];
    if (!same && ++differing <= 3)
      ADD_FAILURE() << what << ": value " << i << " GPU " << gpu[i] << " CPU " << cpu[i];
  }
  EXPECT_EQ(differing, 0) << what;
}
}  // namespace

TEST(WindowView, DifferenceViewIsASubtractedTexelByTexelOnTheCpu) {
  headlessContext();
  ViewDifference difference;
  std::string problem;
  // 1. RGBA minus a one-channel texture: B's channel under every channel of A.
  const auto a = testValues(4, 30), b = testValues(1, 31);
  GlTexture textureA = upload(GL_RGBA32F, a, 4), textureB = upload(GL_R32F, b, 1);
  const GlTexture* result = difference.update(textureA, textureB, 0, false, 1, problem);
  ASSERT_NE(result, nullptr) << problem;
  EXPECT_EQ(result->channelCount(), 4);
  std::vector<float> expected(a.size());
  for (size_t i = 0; i < a.size(); ++i) expected[i] = a[i] - b[i / 4];
  expectSameFloats(result->readFloats(), expected, "RGBA - R");
  // 2. Depth layers (far - near) with negatives clipped: uncovered texels become 0.
  std::vector<float> nearValues(size_t(kWidth) * kHeight), farValues(nearValues.size());
  for (size_t i = 0; i < nearValues.size(); ++i) {
    const bool covered = i % 3 != 0;
    nearValues[i] = covered ? 0.25f + 0.001f * float(i % 97) : 1.0f;
    farValues[i] = covered ? nearValues[i] + 0.002f * float(i % 13) : 0.0f;
  }
  GlTexture nearTexture(GL_DEPTH_COMPONENT32F, kWidth, kHeight), farTexture(GL_DEPTH_COMPONENT32F, kWidth, kHeight);
  glTextureSubImage2D(nearTexture.id(), 0, 0, 0, kWidth, kHeight, GL_DEPTH_COMPONENT, GL_FLOAT, nearValues.data());
  glTextureSubImage2D(farTexture.id(), 0, 0, 0, kWidth, kHeight, GL_DEPTH_COMPONENT, GL_FLOAT, farValues.data());
  for (bool clip : {false, true}) {
    result = difference.update(farTexture, nearTexture, 0, clip, 2, problem);
    ASSERT_NE(result, nullptr) << problem;
    EXPECT_EQ(result->channelCount(), 1);
    for (size_t i = 0; i < farValues.size(); ++i) {
      const float d = farValues[i] - nearValues[i];
      expected[i] = clip && d < 0 ? 0.0f : d;
    }
    expected.resize(farValues.size());
    expectSameFloats(result->readFloats(), expected, clip ? "far - near, clipped" : "far - near");
  }
  // 3. One layer of an array (an N-buffer level) minus a 2D texture.
  std::vector<float> layered = testValues(4, 40);
  const auto layer1 = testValues(4, 41);
  layered.insert(layered.end(), layer1.begin(), layer1.end());
  GlTexture array = upload(GL_RGBA32F, layered, 4, 2);
  result = difference.update(array, textureA, 1, false, 3, problem);
  ASSERT_NE(result, nullptr) << problem;
  expected.resize(a.size());
  for (size_t i = 0; i < a.size(); ++i) expected[i] = layer1[i] - a[i];
  expectSameFloats(result->readFloats(), expected, "array layer 1 - 2D");
  // 4. Cached per generation (the pipeline's run count): new contents show on the next one.
  const std::vector<float> before = result->readFloats();
  const auto layer0 = testValues(4, 40);
  glTextureSubImage2D(textureA.id(), 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, layer0.data());
  expectSameFloats(difference.update(array, textureA, 1, false, 3, problem)->readFloats(), before, "cached");
  for (size_t i = 0; i < a.size(); ++i) expected[i] = layer1[i] - layer0[i];
  expectSameFloats(difference.update(array, textureA, 1, false, 4, problem)->readFloats(), expected,
                   "next generation");
  GlTexture small(GL_R32F, 8, 8);
  EXPECT_EQ(difference.update(textureA, small, 0, false, 5, problem), nullptr);
  EXPECT_NE(problem.find("37x23"), std::string::npos) << problem;
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

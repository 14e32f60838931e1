// The §3.1 hash lesson (lessons/hash_quality_3_1.json) played through under Xvfb: its figures
// exist, the one-ray shadow is noise with md5_16 and hard with md5_4 (every sample at one
// spot of the light), md5_4's pair histogram is one cell, and the verdicts turn red for lcg32.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>

#include <cmath>
#include <filesystem>

#include "io/image_export.h"
#include "support/command.h"
#include "support/window_test.h"

namespace fs = std::filesystem;

namespace {

std::vector<float> pixels(const fs::path& png, int& width, int& height) {
  OIIO::ImageBuf image(png.string());
  EXPECT_TRUE(image.read()) << png << ": " << image.geterror();
  width = image.spec().width, height = image.spec().height;
  std::vector<float> rgb(size_t(width) * height * 3);
  image.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, rgb.data());
  return rgb;
}

// Mean |I(x+1, y) - I(x, y)| of the red channel.
double roughness(const fs::path& png) {
  int width = 0, height = 0;
  const auto rgb = pixels(png, width, height);
  double sum = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x + 1 < width; ++x)
      sum += std::abs(rgb[(size_t(y) * width + x + 1) * 3] - rgb[(size_t(y) * width + x) * 3]);
  return sum / (double(width - 1) * height);
}

}  // namespace

TEST(WindowHashLesson, BadHashesShowInTheShadowTheHistogramAndTheTable) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("lesson_hash");
  ASSERT_TRUE(playLesson(std::string(PENUMBRA_SOURCE_DIR) + "/lessons/hash_quality_3_1.json", 4,
                         {"a_md5_16_shadow.png", "a_md5_16_pairs.png", "b_md5_4_shadow.png",
                          "b_md5_4_pairs.png", "c_lcg32_shadow.png", "c_lcg32_pairs.png",
                          "d_lcg32_verdicts.png", "e_md5_16_verdicts.png"},
                         dir));
  // One ray per pixel: md5_16 scatters the samples (noise), md5_4 puts them all at one spot.
  const double noisy = roughness(dir / "a_md5_16_shadow.png");
  const double hard = roughness(dir / "b_md5_4_shadow.png");
  EXPECT_GT(noisy, 3 * hard) << noisy << " vs " << hard;
  // md5_4's pair histogram: every cell of the 64 x 64 histogram but one is empty (the raw
  // counts of the EXR: the PNG is annotated, enlarged under its colour bar).
  int width = 0, height = 0;
  std::vector<std::string> names;
  const auto histogram = readExr(dir / "b_md5_4_pairs.exr", width, height, names);
  ASSERT_EQ(width * height, 4096);
  int empty = 0;
  for (float count : histogram) empty += count == 0;
  EXPECT_GE(empty, 4095 - 1);
  int pngWidth = 0, pngHeight = 0;
  pixels(dir / "b_md5_4_pairs.png", pngWidth, pngHeight);
  EXPECT_EQ(pngWidth, 64 * 7) << "a small output is enlarged before it is annotated";
  // Verdicts (0 passed, 0.5 weak, 1 failed, -1 not applicable; red on the colour bar): lcg32
  // mostly failed, md5_16 mostly passed. Read from the EXRs: the PNGs are annotated, the
  // enlarged table on a wider canvas under its colour bar.
  const auto failedCells = [&](const char* name) {
    const auto verdicts = readExr(dir / name, width, height, names);
    int failed = 0;
    for (float verdict : verdicts) failed += verdict > 0.75f;
    return double(failed) / (width * height);
  };
  EXPECT_GT(failedCells("d_lcg32_verdicts.exr"), 0.7);
  EXPECT_LT(failedCells("e_md5_16_verdicts.exr"), 0.2);
  EXPECT_GT(pixels(dir / "d_lcg32_verdicts.png", pngWidth, pngHeight).size(), 0u);
  EXPECT_GT(pngHeight, 160) << "the verdict table is annotated (a colour bar under it)";
  fs::remove_all(dir);
}

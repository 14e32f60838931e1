// The 4D rasterization lesson (lessons/wang_tables.json) played through under Xvfb: its 16
// figures exist and show what its texts say: more pairs per FB pixel with the early rejection
// off (the same colour range), the same image with row masks off, banding at 8x8 light
// samples that 64x64 smooths, more pairs with a bigger light, a mask with both hidden and
// lit cells, and an error against Embree at the same samples that is zero but for a few
// pixels, counted in its caption.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>

#include <cmath>
#include <filesystem>

#include <fstream>
#include <sstream>

#include "io/image_export.h"
#include "support/command.h"
#include "support/window_test.h"

namespace fs = std::filesystem;

namespace {

// Mean of R + G + B over the image, in [0, 3].
double brightness(const fs::path& png) {
  OIIO::ImageBuf image(png.string());
  EXPECT_TRUE(image.read()) << png << ": " << image.geterror();
  const int width = image.spec().width, height = image.spec().height;
  std::vector<float> rgb(size_t(width) * height * 3);
  image.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, rgb.data());
  double sum = 0;
  for (float v : rgb) sum += v;
  return sum / (double(width) * height);
}

// Mean of an exported EXR's first channel (the raw counts behind an annotated PNG).
double exrMean(const fs::path& exr, int* nonZero = nullptr) {
  int width = 0, height = 0;
  std::vector<std::string> names;
  const std::vector<float> values = readExr(exr, width, height, names);
  double sum = 0;
  int count = 0;
  for (size_t i = 0; i < values.size(); i += names.size()) sum += values[i], count += values[i] != 0;
  if (nonZero) *nonZero = count;
  return values.empty() ? 0 : sum / double(values.size() / names.size());
}

// Number of distinct grey levels (red channel, 8 bits): banding has few.
int greyLevels(const fs::path& png) {
  OIIO::ImageBuf image(png.string());
  EXPECT_TRUE(image.read()) << png;
  const int width = image.spec().width, height = image.spec().height;
  std::vector<unsigned char> rgb(size_t(width) * height * 3);
  image.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::UINT8, rgb.data());
  bool seen[256] = {};
  int levels = 0;
  for (size_t i = 0; i < rgb.size(); i += 3) levels += !seen[rgb[i]], seen[rgb[i]] = true;
  return levels;
}

}  // namespace

TEST(WindowWangLesson, FiguresShowWhatTheTextsSay) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("lesson_wang");
  ASSERT_TRUE(playLesson(
      std::string(PENUMBRA_SOURCE_DIR) + "/lessons/wang_tables.json", 8,
      {"a_visibility.png", "b_fb_triangles.png", "c_fb_samples_L0.png", "d_fb_samples_proj4.png",
       "e_fb_pairs_rejection_off.png", "f_fb_pairs_rejection_on.png",
       "g_visibility_row_masks_off.png", "h_visibility_8x8.png", "i_visibility_16x16.png",
       "j_visibility_64x64.png", "k_visibility_light_half.png", "l_fb_pairs_light_half.png",
       "m_fb_pairs_light_double.png", "n_visibility_light_double.png",
       "o_mask_of_one_pixel.png", "p_error_against_embree.png"},
      dir));
  // Table 2 / 7: the same range, fewer pairs with the rejection on; Table 5: more with a
  // bigger light. The perceptual colormap brightens with the count.
  // (The count panels are annotated, so their raw values are compared, from the EXRs.)
  EXPECT_GT(exrMean(dir / "e_fb_pairs_rejection_off.exr"), exrMean(dir / "f_fb_pairs_rejection_on.exr"));
  EXPECT_GT(exrMean(dir / "m_fb_pairs_light_double.exr"), exrMean(dir / "l_fb_pairs_light_half.exr"));
  // Row masks change the work, not the image.
  EXPECT_DOUBLE_EQ(brightness(dir / "g_visibility_row_masks_off.png"), brightness(dir / "a_visibility.png"));
  // Table 4: 8x8 samples quantise visibility to 65 levels; 64x64 has many more.
  EXPECT_LE(greyLevels(dir / "h_visibility_8x8.png"), 65);
  EXPECT_GT(greyLevels(dir / "j_visibility_64x64.png"), 2 * greyLevels(dir / "h_visibility_8x8.png"));
  // One penumbra pixel: hidden and lit cells both; the error against Embree: black.
  const double mask = brightness(dir / "o_mask_of_one_pixel.png");
  EXPECT_GT(mask, 0.3);
  EXPECT_LT(mask, 2.7);
  // Against Embree at the same samples: all but a few grazing pixels agree, and the
  // caption counts those that differ (the number recomputed here from the EXR).
  int differing = -1;
  exrMean(dir / "p_error_against_embree.exr", &differing);
  EXPECT_LE(differing, 128 * 96 / 100);
  std::ifstream md(dir / "lesson.md");
  std::stringstream text;
  text << md.rdbuf();
  EXPECT_NE(text.str().find(std::to_string(differing) + " of " + std::to_string(128 * 96) + " pixels differ"),
            std::string::npos) << text.str();
  fs::remove_all(dir);
}

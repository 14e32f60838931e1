// A lesson's crop (app/window/script/ui_lesson_crop.h, thesis Fig 3.5): exported panels hold
// only the rectangle, and {crop.*} numbers are the error over the counted pixels inside it.
// Oracle: the same run's uncropped EXRs (the error stage's signed error, the classify mask),
// the rectangle's numbers recomputed here pixel by pixel.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "io/image_export.h"
#include "support/command.h"
#include "support/window_test.h"

namespace fs = std::filesystem;

namespace {

const char* kSetup = R"([{"scene": "cube"}, {"eye_size": [120, 90]},
  {"set": {"reference.enabled": true, "reference.samples": 4, "reference.background": false,
           "trace.rays": 1, "error.method": "trace"}},
  {"two_views": true}, {"view": 1}, {"select_output": "error.signed"}, {"view": 0},
  {"select_output": "trace.visibility"}, {"wait": 2},)";

// The value printed after `label` in the output ("crop: 0.1234 57 ..."), in order.
std::vector<double> printedNumbers(const std::string& output, const std::string& label) {
  std::vector<double> numbers;
  const size_t at = output.find(label);
  if (at == std::string::npos) return numbers;
  const std::string line = output.substr(at + label.size(), output.find('\n', at) - at - label.size());
  for (size_t i = 0; i < line.size();) {
    size_t used = 0;
    try {
      numbers.push_back(std::stod(line.substr(i), &used));
      i += used;
    } catch (const std::exception&) {
      ++i;
    }
  }
  return numbers;
}

bool pngSize(const fs::path& png, int& width, int& height) {
  OIIO::ImageBuf image(png.string());
  if (!image.read()) return false;
  width = image.spec().width;
  height = image.spec().height;
  return true;
}

}  // namespace

TEST(WindowLessonCrop, CroppedPanelsAndNumbersCoverOnlyTheRectangle) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("lesson_crop");
  const int cx = 30, cy = 20, cw = 50, ch = 40;  // image coordinates, row 0 at the top
  const auto script = writeScript(dir, std::string(kSetup) + R"(
    {"export_view": "full.exr"},
    {"view": 1}, {"export_view": "signed.exr"}, {"view": 0},
    {"select_output": "classify.mask"}, {"export_view": "mask.exr"},
    {"select_output": "trace.visibility"},
    {"crop": [30, 20, 50, 40]},
    {"export_view": "crop.exr"}, {"export_view": "crop.png"},
    {"say": "crop: {crop.pixels} {crop.rmse} {crop.meanSigned} {crop.max}"},
    {"crop": "none"}, {"export_view": "uncropped.png"}])");
  const auto result = runPenumbra("--script " + script.string() + " --export " + dir.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;

  int w = 0, h = 0, cropW = 0, cropH = 0, sw = 0, sh = 0, mw = 0, mh = 0;
  std::vector<std::string> names;
  const auto full = readExr(dir / "full.exr", w, h, names);
  const auto signedError = readExr(dir / "signed.exr", sw, sh, names);
  const auto mask = readExr(dir / "mask.exr", mw, mh, names);
  const auto cropped = readExr(dir / "crop.exr", cropW, cropH, names);
  ASSERT_EQ(w, 120);
  ASSERT_EQ(h, 90);
  ASSERT_EQ(sw * sh, w * h);
  ASSERT_EQ(mw * mh, w * h);
  ASSERT_EQ(cropW, cw);
  ASSERT_EQ(cropH, ch);
  int pngW = 0, pngH = 0;
  ASSERT_TRUE(pngSize(dir / "crop.png", pngW, pngH));
  EXPECT_EQ(pngW, cw);
  EXPECT_EQ(pngH, ch);
  ASSERT_TRUE(pngSize(dir / "uncropped.png", pngW, pngH));  // "none" goes back to the whole
  EXPECT_EQ(pngW, 120);

  // The crop's texels are the full image's texels at the same place (EXR rows: GL order).
  int differing = 0;
  for (int y = 0; y < ch; ++y)
    for (int x = 0; x < cw; ++x)
      differing += cropped[size_t((ch - 1 - y) * cw + x)] !=
                   full[size_t((h - 1 - (cy + y)) * w + cx + x)];
  EXPECT_EQ(differing, 0);

  // The numbers: counted pixels (neither background 0 nor outside 4) inside the rectangle.
  double sumSquared = 0, sumSigned = 0, maxAbs = 0;
  int counted = 0;
  for (int y = cy; y < cy + ch; ++y)
    for (int x = cx; x < cx + cw; ++x) {
      const size_t i = size_t((h - 1 - y) * w + x);
      const int pixelClass = int(std::lround(mask[i]));
      if (pixelClass == 0 || pixelClass == 4) continue;
      const double e = signedError[i];
      sumSquared += e * e;
      sumSigned += e;
      maxAbs = std::max(maxAbs, std::fabs(e));
      ++counted;
    }
  ASSERT_GT(counted, 100) << "the rectangle should hold receivers";
  const std::vector<double> printed = printedNumbers(result.output, "crop: ");
  ASSERT_EQ(printed.size(), 4u) << result.output;
  EXPECT_EQ(printed[0], counted);
  EXPECT_NEAR(printed[1], std::sqrt(sumSquared / counted), 1e-3 * std::sqrt(sumSquared / counted) + 1e-6);
  EXPECT_NEAR(printed[2], sumSigned / counted, 1e-3 * std::fabs(sumSigned / counted) + 1e-6);
  EXPECT_NEAR(printed[3], maxAbs, 1e-3 * maxAbs + 1e-6);
  EXPECT_GT(maxAbs, 0.0) << "a 1-ray trace differs from the reference somewhere";
}

TEST(WindowLessonCrop, ACropPastTheImageOrWithoutOneIsRefused) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("lesson_crop_bad");
  const auto past = runPenumbra("--script " +
                                writeScript(dir, std::string(kSetup) +
                                                     R"({"crop": [100, 0, 40, 10]}, {"export_view": "x.png"}])")
                                    .string() +
                                " --export " + dir.string());
  EXPECT_EQ(past.exitCode, 2) << past.output;  // a script error, like any other
  EXPECT_NE(past.output.find("reaches past the 120x90 image"), std::string::npos) << past.output;
  const auto none = runPenumbra("--script " +
                                writeScript(dir, std::string(kSetup) + R"({"say": "{crop.rmse}"}])").string() +
                                " --export " + dir.string());
  EXPECT_EQ(none.exitCode, 2) << none.output;  // a script error, like any other
  EXPECT_NE(none.output.find("no crop is set"), std::string::npos) << none.output;
  const auto shape = runPenumbra("--script " + writeScript(dir, R"([{"crop": [1, 2, 0, 4]}])").string());
  EXPECT_EQ(shape.exitCode, 2) << shape.output;
  EXPECT_NE(shape.output.find("expected [x, y, width, height]"), std::string::npos) << shape.output;
}

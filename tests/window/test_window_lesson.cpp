// The window's teaching features under Xvfb, driven as a user would: a lesson played through
// exports its figures (thesis Fig 3.2: the noise falls with more rays and with the filter),
// Alt+drag and Alt+wheel move and scale the light, the thickness view is far - near of the
// exported layers, and the linear search's trace shows its samples and refinements.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "figures/figure_sheet.h"
#include "io/image_export.h"
#include "support/command.h"
#include "support/window_test.h"

namespace fs = std::filesystem;

namespace {

// Mean |I(x+1, y) - I(x, y)| over the gray values of a PNG: high for Monte Carlo noise.
double roughness(const fs::path& png) {
  OIIO::ImageBuf image(png.string());
  EXPECT_TRUE(image.read()) << png;
  const int width = image.spec().width, height = image.spec().height;
  std::vector<float> pixels(size_t(width) * height * image.spec().nchannels);
  image.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, pixels.data());
  const int channels = image.spec().nchannels;
  double sum = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x + 1 < width; ++x)
      sum += std::abs(pixels[(size_t(y) * width + x + 1) * channels] - pixels[(size_t(y) * width + x) * channels]);
  return sum / (double(width - 1) * height);
}

}  // namespace

TEST(WindowLesson, Fig32LessonExportsFiguresWhoseNoiseFallsWithRaysAndFilter) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("lesson_fig32");
  const std::vector<std::string> figures = {"b_1_ray_unfiltered.png", "c_4_rays_unfiltered.png",
                                            "d_16_rays_unfiltered.png", "e_16_rays_filtered.png",
                                            "f_filter_minus_trace.png"};
  CommandResult result;
  ASSERT_TRUE(playLesson(std::string(PENUMBRA_SOURCE_DIR) + "/lessons/fig_3_2_progression.json", 5,
                         figures, dir, &result));
  EXPECT_NE(result.output.find("lesson step 1/5: Thesis §3, Fig 3.2"), std::string::npos) << result.output;
  for (const std::string& name : figures) {
    OIIO::ImageBuf image((dir / name).string());
    ASSERT_TRUE(image.read()) << name << ": " << image.geterror();
    EXPECT_EQ(image.spec().width, 640) << name;
    if (name == figures.back())  // the difference carries its colour bar below the image
      EXPECT_GT(image.spec().height, 480) << name;
    else
      EXPECT_EQ(image.spec().height, 480) << name;
    const auto stats = OIIO::ImageBufAlgo::computePixelStats(image);
    EXPECT_GT(stats.max[0] - stats.min[0], 0.3) << name << " looks blank";
    EXPECT_GT(stats.stddev[0], 0.01) << name << " looks flat";
  }
  // Fig 3.2 (b) -> (e): each step is smoother than the one before.
  const double one = roughness(dir / figures[0]), four = roughness(dir / figures[1]);
  const double sixteen = roughness(dir / figures[2]), filtered = roughness(dir / figures[3]);
  EXPECT_GT(one, 1.3 * four) << one << " " << four;
  EXPECT_GT(four, 1.3 * sixteen) << four << " " << sixteen;
  EXPECT_GT(sixteen, 1.3 * filtered) << sixteen << " " << filtered;
  // The lesson's figure sheet (docs/lessons.md) (its five panels, 3 + 2) as PNG and PDF, and its
  // text.
  OIIO::ImageBuf sheet((dir / "figure_sheet.png").string());
  ASSERT_TRUE(sheet.read()) << sheet.geterror();
  const SheetSize expected = figureSheetSize(5);
  EXPECT_EQ(sheet.spec().width, expected.width);
  EXPECT_EQ(sheet.spec().height, expected.height);
  EXPECT_EQ(expected.width, 2 * kSheetMargin + 3 * kSheetCell + 2 * kSheetGap);  // 3 columns
  EXPECT_EQ(expected.height, 2 * kSheetMargin + kSheetTitle + 2 * (kSheetImage + kSheetCaption) + kSheetGap);
  EXPECT_GT(OIIO::ImageBufAlgo::computePixelStats(sheet).stddev[0], 0.05) << "the sheet looks blank";
  std::ifstream pdf(dir / "figure_sheet.pdf", std::ios::binary);
  std::string head(5, '\0');
  ASSERT_TRUE(pdf.read(head.data(), 5));
  EXPECT_EQ(head, "%PDF-");
  EXPECT_GT(fs::file_size(dir / "figure_sheet.pdf"), 10000u);
  std::ifstream text(dir / "lesson.md");
  const std::string markdown((std::istreambuf_iterator<char>(text)), std::istreambuf_iterator<char>());
  EXPECT_NE(markdown.find("- (e) `f_filter_minus_trace.png`: filter.visibility - trace.visibility"),
            std::string::npos) << markdown;
  EXPECT_NE(markdown.find("5. What did the filter change?"), std::string::npos) << markdown;
  fs::remove_all(dir);
}

TEST(WindowLesson, AltDragMovesTheLightOverTheGroundAndAltWheelScalesIt) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("lesson_light");
  const auto script = writeScript(dir, R"([{"eye_size": [320, 240]}, {"zoom": 0.6},
    {"save_settings": ")" + (dir / "before.json").string() + R"("},
    {"drag": {"from": [160, 150], "to": [100, 150], "keys": "alt"}},
    {"save_settings": ")" + (dir / "moved.json").string() + R"("},
    {"wheel": {"at": [160, 150], "amount": 2, "keys": "alt"}},
    {"wheel": {"at": [160, 150], "amount": 1, "keys": "alt+shift"}},
    {"drag": {"from": [160, 150], "to": [200, 150]}},
    {"save_settings": ")" + (dir / "scaled.json").string() + R"("},
    {"screenshot": ")" + (dir / "outline.png").string() + R"("}])");
  const auto result = runPenumbra("--script " + script.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const auto light = [&](const char* name) {
    std::ifstream in(dir / name);
    return nlohmann::json::parse(in)["light"];
  };
  const auto before = light("before.json"), moved = light("moved.json"), scaled = light("scaled.json");
  // Dragged 60 pixels to the left on the ground: the light moves left, at its height.
  const double dx = moved["center"][0].get<double>() - before["center"][0].get<double>();
  EXPECT_LT(dx, -0.3) << moved.dump();
  EXPECT_EQ(moved["center"][1], before["center"][1]);
  EXPECT_EQ(moved["width"], before["width"]);
  // Alt+wheel 2: both sides x 1.21; Alt+Shift+wheel 1: the width alone x 1.1; a drag without
  // Alt pans the view and leaves the light alone.
  EXPECT_NEAR(scaled["width"].get<double>(), before["width"].get<double>() * 1.331, 1e-4);
  EXPECT_NEAR(scaled["height"].get<double>(), before["height"].get<double>() * 1.21, 1e-4);
  EXPECT_EQ(scaled["center"], moved["center"]);
  // The outline (yellow: 255, 200, 40) is drawn in the view.
  OIIO::ImageBuf shot((dir / "outline.png").string());
  ASSERT_TRUE(shot.read());
  const int width = shot.spec().width, height = shot.spec().height;
  std::vector<float> rgb(size_t(width) * height * 3);
  shot.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, rgb.data());
  int yellow = 0;
  for (size_t i = 0; i < rgb.size(); i += 3)
    yellow += rgb[i] > 0.95f && std::abs(rgb[i + 1] - 0.784f) < 0.03f && rgb[i + 2] < 0.25f;
  EXPECT_GT(yellow, 50) << "no light outline in the screenshot";
  fs::remove_all(dir);
}

TEST(WindowLesson, ThicknessViewIsFarMinusNearWhereCovered) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("lesson_thickness");
  const auto script = writeScript(dir, R"([{"eye_size": [128, 96]},
    {"set": {"light.resolution": 256}}, {"export_all": ")" + (dir / "all").string() + R"("},
    {"thickness": true}, {"wait": 1}, {"export_view": ")" + (dir / "thickness.exr").string() + R"("},
    {"clip_negative": false}, {"export_view": ")" + (dir / "signed.exr").string() + R"("}])");
  const auto result = runPenumbra("--script " + script.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  int w = 0, h = 0;
  std::vector<std::string> channels;
  const auto nearValues = readExr(dir / "all" / "light_layers.near.exr", w, h, channels);
  const auto farValues = readExr(dir / "all" / "light_layers.far.exr", w, h, channels);
  const auto thickness = readExr(dir / "thickness.exr", w, h, channels);
  EXPECT_EQ(channels, std::vector<std::string>{"lsDepthFar-lsDepthNear"});
  const auto signedValues = readExr(dir / "signed.exr", w, h, channels);
  ASSERT_EQ(thickness.size(), nearValues.size());
  ASSERT_EQ(signedValues.size(), nearValues.size());
  int covered = 0;
  for (size_t i = 0; i < nearValues.size(); ++i) {
    const float d = farValues[i] - nearValues[i];
    EXPECT_EQ(signedValues[i], d) << i;
    EXPECT_EQ(thickness[i], d < 0 ? 0.0f : d) << i;
    if (nearValues[i] < 1.0f) {
      ++covered;
      EXPECT_GE(d, 0.0f) << "a covered texel has far < near: " << i;
    }
  }
  EXPECT_GT(covered, 100);
  fs::remove_all(dir);
}

TEST(WindowLesson, LinearSearchTraceShowsSamplesAndRefinementPoints) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("lesson_linear");
  int x = -1, y = -1;
  ASSERT_TRUE(penumbraPixel(dir, x, y)) << "no penumbra pixel in the cube scene";
  const std::string pick = nlohmann::json::array({x, y}).dump();
  const auto script = writeScript(dir, R"([{"eye_size": [160, 120]},
    {"set": {"trace.search": "linear_binary", "trace.linear_step": 4, "trace.shorten_rays": false}},
    {"select_output": "composite.color"}, {"pick": )" + pick + R"(}, {"wait": 2},
    {"print_pick": "linear"},
    {"set": {"trace.search": "hierarchical"}}, {"wait": 2}, {"print_pick": "hierarchical"}])");
  const auto result = runPenumbra("--script " + script.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const size_t linear = result.output.find("pick linear");
  const size_t hierarchical = result.output.find("pick hierarchical");
  ASSERT_NE(linear, std::string::npos) << result.output;
  ASSERT_NE(hierarchical, std::string::npos) << result.output;
  const size_t points = result.output.find("trace points: ", linear);
  ASSERT_LT(points, hierarchical) << result.output;
  EXPECT_GE(std::atoi(result.output.c_str() + points + 14), 2) << result.output;
  EXPECT_NE(result.output.find("trace points: 0 samples, 0 refinements", hierarchical), std::string::npos)
      << result.output;
  fs::remove_all(dir);
}

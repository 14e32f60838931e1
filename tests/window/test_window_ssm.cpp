// What a user does (docs/ssm_pcss.md) for soft shadow maps, driven through the window by --script
// under Xvfb: a student selects ssm, watches the soft shadow map fill up (ssm.fill), picks a
// penumbra pixel and sees its back-projected micro-patches on the light (ssm.pickedLight), switches
// one pass -> two passes and R32F -> R16F and sees the error view change.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>

#include "io/image_export.h"
#include "support/command.h"
#include "support/window_test.h"

namespace fs = std::filesystem;

namespace {

// One channel of an EXR, by name ("" = the first); OpenEXR keeps channels sorted by name.
std::vector<float> exr(const fs::path& path, const std::string& channel = "") {
  int w = 0, h = 0;
  std::vector<std::string> names;
  const std::vector<float> values = readExr(path, w, h, names);
  const size_t c = channel.empty() ? 0 : size_t(std::find(names.begin(), names.end(), channel) - names.begin());
  EXPECT_LT(c, names.size()) << path << " has no channel " << channel;
  std::vector<float> one;
  for (size_t i = c; i < values.size() && c < names.size(); i += names.size()) one.push_back(values[i]);
  return one;
}

double mean(const std::vector<float>& values) {
  return std::accumulate(values.begin(), values.end(), 0.0) / double(std::max<size_t>(values.size(), 1));
}

int differing(const std::vector<float>& a, const std::vector<float>& b) {
  int count = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) count += std::abs(a[i] - b[i]) > 1e-6f;
  return count;
}

}  // namespace

TEST(WindowSsm, PickFillPassesAndFormatChangeWhatTheStudentSees) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("window_ssm");
  const int w = 160, h = 120;
  // 1. A penumbra pixel of ssm on the cube, found with the headless export (GL rows).
  ASSERT_EQ(runPenumbra("export --scene cube --width 160 --height 120 --out " + (dir / "cli").string()).exitCode, 0);
  const std::vector<float> cliVisibility = exr(dir / "cli" / "ssm.visibility.exr");
  int x = -1, y = -1;
  float picked = 0;
  for (int i = 0; i < w * h && x < 0; ++i)
    if (cliVisibility[size_t(i)] > 0.35f && cliVisibility[size_t(i)] < 0.65f) {
      x = i % w;
      y = h - 1 - i / w;  // image coordinates: row 0 at the top
      picked = cliVisibility[size_t(i)];
    }
  ASSERT_GE(x, 0) << "no ssm penumbra pixel on the cube";

  // 2. The student's path through the window.
  const auto path = [&](const char* name) { return (dir / name).string(); };
  const auto script = writeScript(dir, R"([
    {"eye_size": [160, 120]},
    {"set": {"composite.shadow": "ssm", "error.method": "ssm", "reference.enabled": true,
             "reference.samples": 8, "reference.cache": false, "ssm.fill": 0.5}},
    {"select_stage": "ssm"}, {"select_output": "ssm.softShadowMap"}, {"wait": 1},
    {"export_view": ")" + path("half.exr") + R"("},
    {"set": {"ssm.fill": 1.0}}, {"wait": 1}, {"export_view": ")" + path("full.exr") + R"("},
    {"select_output": "ssm.visibility"},
    {"pick": [)" + std::to_string(x) + ", " + std::to_string(y) + R"(]}, {"wait": 2},
    {"print_pick": "ssm"},
    {"select_output": "ssm.pickedLight"}, {"wait": 1},
    {"export_view": ")" + path("picked.exr") + R"("}, {"screenshot": ")" + path("picked.png") + R"("},
    {"select_output": "error.absolute"}, {"wait": 1},
    {"export_view": ")" + path("one_r32f.exr") + R"("},
    {"set": {"ssm.passes": "two"}}, {"wait": 1}, {"export_view": ")" + path("two_r32f.exr") + R"("},
    {"set": {"ssm.accumulation": "r16f"}}, {"wait": 1},
    {"export_view": ")" + path("two_r16f.exr") + R"("}])");
  const auto result = runPenumbra("--scene cube --script " + script.string() + " --width 1000 --height 700");
  ASSERT_EQ(result.exitCode, 0) << result.output;

  // The fill slider draws half the micro-patches: some occlusion, less than all of them.
  const double half = mean(exr(dir / "half.exr", "occlusionFront")), full = mean(exr(dir / "full.exr", "occlusionFront"));
  EXPECT_GT(half, 0.0);
  EXPECT_LT(half, 0.9 * full);
  // The pick went to ssm as an eye pixel (row 0 at the top), and the picked light shows the
  // back-projected patches: covered points, gaps, and on average the receiver's occlusion
  // (the count of patches over the light, averaged, is the sum of their clipped fractions).
  EXPECT_NE(result.output.find("ssm.visibility " + std::to_string(picked).substr(0, 6)), std::string::npos)
      << result.output;
  const std::vector<float> cover = exr(dir / "picked.exr", "coverFront");
  const double covered = mean(cover);
  const float most = *std::max_element(cover.begin(), cover.end());
  const float least = *std::min_element(cover.begin(), cover.end());
  std::printf("picked (%d, %d): ssm visibility %.4f; picked light: mean cover %.4f, max %.0f, min %.0f\n",
              x, y, picked, covered, most, least);
  EXPECT_GE(most, 1.0f);
  EXPECT_EQ(least, 0.0f);
  EXPECT_NEAR(covered, 1.0 - picked, 0.01);  // measured: 0.0012 (the 256^2 raster of the patches)
  // One pass -> two passes and R32F -> R16F change the error view.
  const auto one = exr(dir / "one_r32f.exr"), two = exr(dir / "two_r32f.exr"),
             two16 = exr(dir / "two_r16f.exr");
  std::printf("error view: mean |e| one pass %.5f, two passes %.5f, two passes r16f %.5f; "
              "pixels changed %d (passes), %d (format)\n",
              mean(one), mean(two), mean(two16), differing(one, two), differing(two, two16));
  EXPECT_GT(differing(one, two), 50);
  EXPECT_GT(differing(two, two16), 50);
  EXPECT_LE(mean(two), mean(one));  // §4.2.3: two passes never worse on a thick occluder
  fs::remove_all(dir);
}

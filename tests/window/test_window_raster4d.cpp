// What a user does (docs/raster4d.md) in the window, driven by --script under Xvfb: a student
// selects raster4d, picks a penumbra pixel and sees its 32 x 32 mask on the light (occluded cells
// counted against the pixel's visibility); switches the early rejection off and the pairs tested
// grow (the time too, but it is not asserted: the machine is shared); the error view against Embree
// at the same samples is black (at most one tie bit per pixel).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>
#include <string>

#include "io/image_export.h"
#include "support/command.h"
#include "support/window_test.h"

namespace fs = std::filesystem;

namespace {

// The value printed as "  <name> <value>" in the block that the line "<header>..." starts
// (the indented lines right after it), -1 if none: a counter missing from one block is not
// read from the next.
double printedValue(const std::string& output, const std::string& header, const std::string& name) {
  size_t start = output.rfind(header, 0) == 0 ? 0 : output.find("\n" + header);
  if (start == std::string::npos) return -1;
  start = output.find('\n', start + 1);  // the end of the header line
  const std::string prefix = "  " + name + " ";
  while (start != std::string::npos && output.compare(start + 1, 2, "  ") == 0) {
    const size_t end = output.find('\n', start + 1);
    const std::string line = output.substr(start + 1, end == std::string::npos ? end : end - start - 1);
    if (line.rfind(prefix, 0) == 0) return std::stod(line.substr(prefix.size()));
    start = end;
  }
  return -1;
}

}  // namespace

TEST(WindowRaster4d, MaskOfAPickedPixelRejectionAndErrorAgainstEmbree) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("window_raster4d");
  const auto script = writeScript(dir, R"([{"eye_size": [64, 48]},
    {"set": {"raster4d.enabled": true}}, {"select_output": "raster4d.visibility"},
    {"pick": [50, 33]}, {"wait": 1}, {"print_pick": "penumbra"},
    {"view": 1}, {"select_output": "raster4d.pickedMask"}, {"wait": 1},
    {"export_view": ")" + (dir / "mask.exr").string() + R"("},
    {"print_counters": "rejection on"},
    {"set": {"raster4d.early_rejection": false}}, {"wait": 1}, {"print_counters": "rejection off"},
    {"set": {"raster4d.early_rejection": true, "reference.enabled": true,
             "reference.sampling": "uniform", "reference.samples": 32,
             "error.method": "raster4d", "error.against": "reference"}},
    {"select_output": "error.absolute"}, {"wait": 3}, {"print_counters": "error"}])");
  const auto result = runPenumbra("--scene spheres --script " + script.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;

  // 1. The picked pixel is in the penumbra, and its mask says why: 1 - blocked cells / 1024.
  const double visibility = printedValue(result.output, "pick penumbra:", "raster4d.visibility");
  EXPECT_GT(visibility, 0.05) << result.output;
  EXPECT_LT(visibility, 0.95) << result.output;
  int width = 0, height = 0;
  std::vector<std::string> channels;
  const std::vector<float> mask = readExr(dir / "mask.exr", width, height, channels);
  ASSERT_EQ(width, 32);
  ASSERT_EQ(height, 32);
  int blocked = 0;
  for (float cell : mask) blocked += cell > 0;
  // print_pick writes %.9g, not always enough for 1 - k/1024 (odd k needs 10 digits): compare
  // the count of blocked cells, which rounding to 9 digits cannot change, and the value to
  // within that rounding (5e-9 of a value <= 1).
  EXPECT_EQ(blocked, std::lround((1.0 - visibility) * 1024)) << visibility;
  EXPECT_NEAR(1.0 - blocked / 1024.0, visibility, 1e-8);

  // 2. Early rejection off: every pair considered is tested, more than with it on.
  const double considered = printedValue(result.output, "counters rejection on:", "raster4d.pairsConsidered");
  const double keptOn = printedValue(result.output, "counters rejection on:", "raster4d.pairsKept");
  const double keptOff = printedValue(result.output, "counters rejection off:", "raster4d.pairsKept");
  EXPECT_GT(keptOn, 0) << result.output;
  EXPECT_LT(keptOn, keptOff) << result.output;
  EXPECT_EQ(keptOff, considered) << result.output;

  // 3. Against Embree at the very same samples: black but for a tie bit.
  const double worst = printedValue(result.output, "counters error:", "error.max");
  ASSERT_GE(worst, 0) << result.output;
  EXPECT_LE(worst, 1.0 / 1024) << result.output;
  EXPECT_GT(printedValue(result.output, "counters error:", "error.pixelsInShadow"), 100);
  fs::remove_all(dir);
}

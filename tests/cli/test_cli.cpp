// The command line: export writes what it promises; bad flags exit 2 with a clear message.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/command.h"
#include "support/temp_directory.h"

namespace fs = std::filesystem;

TEST(Cli, ExportWritesEveryOutputAndRunJson) {
  const TempDirectory scratch("penumbra_cli_export");
  const fs::path out = scratch.path() / "out";
  const auto result = runPenumbra("export --scene cube --out " + out.string() +
                                  " --width 128 --height 96 --set light.resolution=128");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  for (const char* stem : {"gbuffer.albedo", "gbuffer.wsNormal", "gbuffer.wsPosition",
                           "gbuffer.depth", "light_layers.near", "light_layers.far",
                           "hard_shadow.visibility", "composite.color"}) {
    EXPECT_TRUE(fs::exists(out / (std::string(stem) + ".exr"))) << stem;
    EXPECT_TRUE(fs::exists(out / (std::string(stem) + ".png"))) << stem;
  }
  std::ifstream in(out / "run.json");
  const auto run = nlohmann::json::parse(in);
  EXPECT_EQ(run["scene"], "cube");
  EXPECT_EQ(run["parameters"]["light"]["resolution"], "128");
  // An `auto` parameter is recorded as auto, and what it chose beside it: map 128 has
  // 16,384 x 8 N-buffer texel-levels, 10.7 per pixel of 128 x 96, so the N-buffer.
  EXPECT_EQ(run["parameters"]["trace"]["hierarchy"], "auto");
  bool hierarchyChoice = false;
  for (const auto& reason : run["auto_choices"])
    hierarchyChoice = hierarchyChoice || reason.get<std::string>().rfind("hierarchy nbuffer:", 0) == 0;
  EXPECT_TRUE(hierarchyChoice) << run["auto_choices"].dump();
  EXPECT_TRUE(run["renderer"].get<std::string>().size() > 3);
  EXPECT_TRUE(run["stage_milliseconds"].contains("trace") || run["stage_milliseconds"].contains("hard_shadow"));
  for (const auto& entry : fs::directory_iterator(out))
    EXPECT_EQ(entry.path().string().find(".partial"), std::string::npos) << entry.path();
}

// Bad input is refused before anything is written: --out names a directory that must never
// appear (inside a unique scratch directory).
TEST(Cli, UnknownSetKeyExits2AndListsValidKeys) {
  const TempDirectory scratch("penumbra_cli_never");
  const fs::path never = scratch.path() / "never";
  const auto result = runPenumbra("export --scene cube --out " + never.string() + " --set nope.key=1");
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.output.find("unknown parameter 'nope.key'"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("light.resolution"), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(never));
}

TEST(Cli, OutOfRangeValueExits2AndNamesTheRange) {
  const TempDirectory scratch("penumbra_cli_never");
  const std::string never = (scratch.path() / "never").string();
  const auto result = runPenumbra("export --scene cube --out " + never + " --set light.resolution=5000");
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.output.find("[128, 2048]"), std::string::npos) << result.output;
  const auto notNumber = runPenumbra("export --set hard_shadow.offset=abc --out " + never);
  EXPECT_EQ(notNumber.exitCode, 2);
  EXPECT_NE(notNumber.output.find("hard_shadow.offset"), std::string::npos) << notNumber.output;
  EXPECT_FALSE(fs::exists(never));
}

TEST(Cli, BadFlagsAndScenesExit2) {
  const TempDirectory scratch("penumbra_cli_never");
  const std::string never = (scratch.path() / "never").string();
  EXPECT_EQ(runPenumbra("export --width -3").exitCode, 2);
  EXPECT_EQ(runPenumbra("--no-such-flag").exitCode, 2);
  const auto scene = runPenumbra("export --scene nowhere --out " + never);
  EXPECT_EQ(scene.exitCode, 2);
  EXPECT_NE(scene.output.find("cube, plate, spheres, engine, dragon"), std::string::npos) << scene.output;
  const auto missing = runPenumbra("export --scene /nonexistent/file.glb --out " + never);
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.output.find("file.glb"), std::string::npos) << missing.output;
  EXPECT_FALSE(fs::exists(never));
}

// A camera that sees nothing: the files are written, a loud message, exit status 2
// (docs/accuracy.md).
TEST(Cli, ExportOfAnEmptyFrameExits2) {
  const TempDirectory scratch("penumbra_cli_empty_frame");  // unique: parallel runs never share it
  const fs::path& directory = scratch.path();
  std::ofstream(directory / "away.json") << R"({"objects": [{"ground": {"size": 4}}],
    "light": {"center": [0, 4, 0], "forward": [0, -1, 0], "up": [0, 0, -1], "width": 1, "height": 1},
    "camera": {"position": [0, 1, 0], "target": [0, 5, 0.1], "up": [0, 0, 1]}})";
  const auto result = runPenumbra("export --scene " + (directory / "away.json").string() +
                                   " --out " + (directory / "out").string() + " --width 32 --height 24");
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("sees no geometry"), std::string::npos) << result.output;
  EXPECT_TRUE(fs::exists(directory / "out" / "run.json"));
}

TEST(Window, ScreenshotUnderXvfbIsNotBlank) {
  if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY: run under xvfb-run (make test does)";
  const TempDirectory scratch("penumbra_window_smoke");
  const fs::path shot = scratch.path() / "shot.png";
  const auto result = runPenumbra("--screenshot " + shot.string() + " --frames 3 --width 800 --height 500");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  OIIO::ImageBuf image(shot.string());
  ASSERT_TRUE(image.read()) << image.geterror();
  EXPECT_EQ(image.spec().width, 800);
  const auto stats = OIIO::ImageBufAlgo::computePixelStats(image);
  double spread = 0;
  for (int c = 0; c < 3; ++c) spread += stats.max[c] - stats.min[c];
  EXPECT_GT(spread, 0.5) << "screenshot looks blank";
  // The view (right of the 340-pixel panel) shows the composite, not just background.
  OIIO::ImageBuf view = OIIO::ImageBufAlgo::cut(image, OIIO::ROI(400, 800, 0, 500));
  const auto viewStats = OIIO::ImageBufAlgo::computePixelStats(view);
  EXPECT_GT(viewStats.stddev[0], 0.02);
}

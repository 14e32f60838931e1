// The window driven by `--script` under Xvfb: screenshots of several states are not blank,
// exports made from the window are bit-identical to `penumbra export` with the same settings,
// settings saved by the window reproduce the image through --config, a picked penumbra pixel
// shows its ray's steps, and bad scripts / configs exit 2 with a clear message.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/image_export.h"
#include "support/command.h"
#include "support/window_test.h"

namespace fs = std::filesystem;

namespace {

// Raw float data equal bit for bit (NaN patterns included), and the same channel names.
void expectSameExr(const fs::path& a, const fs::path& b) {
  int wa = 0, ha = 0, wb = 0, hb = 0;
  std::vector<std::string> ca, cb;
  const std::vector<float> va = readExr(a, wa, ha, ca), vb = readExr(b, wb, hb, cb);
  ASSERT_EQ(wa, wb) << a;
  ASSERT_EQ(ha, hb) << a;
  EXPECT_EQ(ca, cb) << a;
  ASSERT_EQ(va.size(), vb.size()) << a;
  EXPECT_EQ(std::memcmp(va.data(), vb.data(), va.size() * sizeof(float)), 0) << a << " vs " << b;
}

}  // namespace

TEST(WindowScript, ScreenshotsOfSeveralStatesAreNotBlank) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("window_shots");
  const auto script = writeScript(dir, R"([
    {"eye_size": [160, 120]},
    {"select_output": "classify.mask"}, {"screenshot": ")" + (dir / "mask.png").string() + R"("},
    {"select_output": "nbuffer.levels"}, {"level": 2}, {"channels": "R"}, {"range": "autofit"},
    {"screenshot": ")" + (dir / "levels.png").string() + R"("},
    {"two_views": true}, {"view": 1}, {"select_output": "gbuffer.wsNormal"}, {"help": true},
    {"screenshot": ")" + (dir / "two.png").string() + R"("}])");
  const auto result = runPenumbra("--script " + script.string() + " --width 1000 --height 700");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  for (const char* name : {"mask.png", "levels.png", "two.png"}) {
    OIIO::ImageBuf image((dir / name).string());
    ASSERT_TRUE(image.read()) << name << ": " << image.geterror();
    EXPECT_EQ(image.spec().width, 1000) << name;
    // The centre column of the window (the views) is an image, not a flat background.
    OIIO::ImageBuf views = OIIO::ImageBufAlgo::cut(image, OIIO::ROI(300, 700, 80, 620));
    const auto stats = OIIO::ImageBufAlgo::computePixelStats(views);
    double spread = 0, deviation = 0;
    for (int c = 0; c < 3; ++c) {
      spread += stats.max[c] - stats.min[c];
      deviation += stats.stddev[c];
    }
    EXPECT_GT(spread, 0.5) << name << " looks blank";
    EXPECT_GT(deviation, 0.05) << name << " looks flat";
  }
  fs::remove_all(dir);
}

TEST(WindowScript, ExportsAreBitIdenticalToPenumbraExport) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("window_export");
  const fs::path fromWindow = dir / "window", fromCli = dir / "cli";
  const auto script = writeScript(dir, R"([
    {"eye_size": [128, 96]}, {"set": {"light.resolution": 128, "trace.rays": 3}},
    {"export_all": ")" + fromWindow.string() + R"("},
    {"select_output": "trace.visibility"},
    {"export_view": ")" + (dir / "view.exr").string() + R"("},
    {"export_view": ")" + (dir / "view.png").string() + R"("}])");
  const auto window = runPenumbra("--script " + script.string());
  ASSERT_EQ(window.exitCode, 0) << window.output;
  EXPECT_NE(window.output.find("files into " + fromWindow.string()), std::string::npos) << window.output;
  const auto cli = runPenumbra("export --scene cube --width 128 --height 96 --set "
                               "light.resolution=128 --set trace.rays=3 --out " + fromCli.string());
  ASSERT_EQ(cli.exitCode, 0) << cli.output;
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(fromCli)) {
    if (entry.path().extension() != ".exr") continue;
    const fs::path twin = fromWindow / entry.path().filename();
    ASSERT_TRUE(fs::exists(twin)) << twin;
    expectSameExr(entry.path(), twin);
    ++compared;
  }
  EXPECT_GE(compared, 10);
  // The view's raw export is the stage's EXR; its PNG (declared display) the export's PNG.
  expectSameExr(dir / "view.exr", fromCli / "trace.visibility.exr");
  OIIO::ImageBuf viewPng((dir / "view.png").string()), cliPng((fromCli / "trace.visibility.png").string());
  const auto difference = OIIO::ImageBufAlgo::compare(viewPng, cliPng, 0, 0);
  EXPECT_EQ(difference.nfail, 0u);
  EXPECT_EQ(difference.maxerror, 0.0);
  std::ifstream windowRun(fromWindow / "run.json"), cliRun(fromCli / "run.json");
  const auto a = nlohmann::json::parse(windowRun), b = nlohmann::json::parse(cliRun);
  EXPECT_EQ(a["parameters"], b["parameters"]);
  EXPECT_EQ(a["eye_size"], b["eye_size"]);
  fs::remove_all(dir);
}

TEST(WindowScript, SavedSettingsReproduceTheImageThroughConfig) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("window_config");
  const fs::path settings = dir / "settings.json";
  const auto first = writeScript(dir, R"([
    {"eye_size": [96, 72]}, {"set": {"light.resolution": 128, "filter.radius": 2}},
    {"camera_orbit": [25, 5]}, {"settings": {"light": {"width": 0.6}}},
    {"save_settings": ")" + settings.string() + R"("},
    {"export_view": ")" + (dir / "first.exr").string() + R"("}])");
  const auto saved = runPenumbra("--script " + first.string());
  ASSERT_EQ(saved.exitCode, 0) << saved.output;
  std::ofstream(dir / "second.json") << R"([{"export_view": ")" + (dir / "second.exr").string() + R"("}])";
  const auto loaded = runPenumbra("--config " + settings.string() + " --script " + (dir / "second.json").string());
  ASSERT_EQ(loaded.exitCode, 0) << loaded.output;
  expectSameExr(dir / "first.exr", dir / "second.exr");
  // And the orbit mattered: the default camera gives another image.
  std::ofstream(dir / "third.json") << R"([{"eye_size": [96, 72]}, {"set": {"light.resolution": 128, "filter.radius": 2}},
    {"export_view": ")" + (dir / "third.exr").string() + R"("}])";
  ASSERT_EQ(runPenumbra("--script " + (dir / "third.json").string()).exitCode, 0);
  int w = 0, h = 0;
  std::vector<std::string> channels;
  EXPECT_NE(readExr(dir / "first.exr", w, h, channels), readExr(dir / "third.exr", w, h, channels));
  fs::remove_all(dir);
}

TEST(WindowScript, PickedPenumbraPixelShowsItsRaySteps) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("window_trace");
  // A penumbra pixel (class 2) found with the headless export, one whose rays reach the search.
  int x = -1, y = -1;
  ASSERT_TRUE(penumbraPixel(dir, x, y)) << "no penumbra pixel in the cube scene";
  const auto script = writeScript(dir, R"([
    {"eye_size": [160, 120]}, {"select_output": "composite.color"},
    {"pick": [)" + std::to_string(x) + ", " + std::to_string(y) + R"(]}, {"wait": 2},
    {"print_pick": "penumbra"}, {"select_ray": 1}, {"wait": 1}, {"print_pick": "ray1"}])");
  const auto result = runPenumbra("--script " + script.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("classify.mask 2\n"), std::string::npos) << result.output;
  const size_t steps = result.output.find("trace steps: ");
  ASSERT_NE(steps, std::string::npos) << result.output;
  EXPECT_GT(std::atoi(result.output.c_str() + steps + 13), 0) << result.output;
  EXPECT_NE(result.output.find("(ray 1 of "), std::string::npos) << result.output;
  fs::remove_all(dir);
}

TEST(WindowScript, BadScriptsAndConfigsExit2WithAClearMessage) {
  const fs::path dir = scratchDirectory("window_bad");
  // Checked before any window opens: works without a display too.
  const auto unknown = writeScript(dir, R"([{"wait": 1}, {"explode": true}])");
  auto result = runPenumbra("--script " + unknown.string());
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("script action 2: unknown action 'explode'"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("select_output"), std::string::npos) << result.output;
  std::ofstream(dir / "broken.json") << "[{\"wait\": ";
  result = runPenumbra("--script " + (dir / "broken.json").string());
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.output.find("not valid JSON"), std::string::npos) << result.output;
  if (!std::getenv("DISPLAY")) return;
  // Found while running: the action names what is valid.
  const auto missing = writeScript(dir, R"([{"select_output": "nope.out"}, {"wait": 1}])");
  result = runPenumbra("--script " + missing.string());
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("script action 1 (select_output): unknown output 'nope.out'"),
            std::string::npos) << result.output;
  EXPECT_NE(result.output.find("trace.visibility"), std::string::npos) << result.output;
  const auto range = writeScript(dir, R"([{"set": {"trace.rays": 99}}])");
  result = runPenumbra("--script " + range.string());
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("trace.rays"), std::string::npos) << result.output;
  std::ofstream(dir / "config.json") << R"({"parameters": {"trace.rays": "many"}})";
  result = runPenumbra("--config " + (dir / "config.json").string() + " --screenshot " +
                       (dir / "never.png").string());
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("/parameters/trace.rays"), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(dir / "never.png"));
  fs::remove_all(dir);
}

// Time on the command line: `export --time` poses an animated scene (run.json says when),
// a time that poses a scene badly and a bad track are input errors (exit 2, the file and
// the JSON pointer named).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/command.h"
#include "support/temp_directory.h"

namespace {

const char* kScene = R"({"objects": [
    {"ground": {"size": 1.5}},
    {"ground": {"size": 1, "y": 1}, "receiver_only": false,
     "animation": {"translate": {"times": [0, 2], "values": [[0, 0, 0], [1, 0, 0]]}}}],
  "light": {"center": [0, 4, 0], "forward": [0, -1, 0], "up": [0, 0, -1], "width": 1, "height": 1},
  "camera": {"position": [0, 3, 6], "target": [0, 0, 0]}})";

nlohmann::json readJson(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

}  // namespace

TEST(CliAnimation, ExportAtTimeWritesTheTimeAndPosedBounds) {
  const TempDirectory dir("penumbra_cli_animation");
  const std::string scene = dir.write("moving.json", kScene);
  const std::string out = (dir.path() / "t1").string();
  const CommandResult result = runPenumbra("export --scene " + scene + " --time 1 --width 32 "
                                           "--height 24 --out " + out);
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("posed at time 1 s"), std::string::npos) << result.output;
  const nlohmann::json run = readJson(out + "/run.json");
  EXPECT_EQ(run["time"].get<double>(), 1.0);
  // The moving square (x in [-0.5, 0.5] at rest) spans [0, 1] at t = 1, past the ground's
  // 0.75: the scene's bounds are the pose's.
  EXPECT_EQ(run["bounds"]["max"][0].get<double>(), 1.0);
}

TEST(CliAnimation, BadTrackIsExitTwoNamingThePointer) {
  const TempDirectory dir("penumbra_cli_animation_bad");
  std::string text = kScene;
  text.replace(text.find("[0, 2]"), 6, "[2, 0]");
  const std::string scene = dir.write("bad.json", text);
  const CommandResult result = runPenumbra("export --scene " + scene + " --width 16 --height 16 "
                                           "--out " + (dir.path() / "out").string());
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find(scene + ": /objects/1/animation/translate/times/1: times must "
                                       "increase: 0 is not after 2"),
            std::string::npos)
      << result.output;
}

TEST(CliAnimation, NonFiniteTimeIsExitTwo) {
  const TempDirectory dir("penumbra_cli_animation_time");
  const CommandResult result = runPenumbra("export --scene light_sweep --time nan --width 16 "
                                           "--height 16 --out " + (dir.path() / "out").string());
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("--time"), std::string::npos) << result.output;
}

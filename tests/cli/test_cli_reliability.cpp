// Reliability on the command line (docs/reliability.md): no abort, no partial export, no silent
// wrong answer. Output paths are checked before rendering (exit 2); an export directory is replaced
// as a whole or not at all, also when the export is killed; extreme scenes are refused or warned
// about; messages stay short and say why.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "support/command.h"
#include "support/refusal.h"
#include "support/scene_writer.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Names in `directory` holding ".partial" (a temporary file or directory left behind).
std::vector<std::string> leftovers(const fs::path& directory) {
  std::vector<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(directory))
    if (contains(entry.path().filename().string(), ".partial")) names.push_back(entry.path());
  return names;
}

const char* kSmall = " --width 32 --height 32 --set light.resolution=128";

}  // namespace

// Case 1: an --out under a file aborted (SIGABRT) after all the timing work.
TEST(CliReliability, BadOutputPathsExit2BeforeAnyRendering) {
  const TempDirectory dir("penumbra_cli_out");
  const std::string file = dir.write("afile", "x");
  const auto stages = runPenumbra("bench-stages --frames 1 --scenes cube --width 16 --height 16 "
                                  "--map 128 --out " + file + "/sub/t.md");
  EXPECT_EQ(stages.exitCode, 2) << stages.output;
  EXPECT_TRUE(contains(stages.output, "is not a directory")) << stages.output;
  EXPECT_FALSE(contains(stages.output, "ms per frame")) << "rendered before checking --out";
  for (const std::string& command :
       {"export --out " + file, "export --out " + file + "/sub", "trace --pixel 1,1 --out " + file + "/t.json",
        "bench --scene cube --preset minimal --out " + file}) {
    const auto result = runPenumbra(command + kSmall);
    EXPECT_EQ(result.exitCode, 2) << command << "\n" << result.output;
    EXPECT_TRUE(contains(result.output, file)) << result.output;
    EXPECT_FALSE(contains(result.output, "stage")) << "rendered before checking: " << result.output;
  }
  // A directory that is not an earlier export is never replaced as a whole.
  dir.write("notes.txt", "mine");
  const auto foreign = runPenumbra("export --out " + dir.path().string() + kSmall);
  EXPECT_EQ(foreign.exitCode, 2) << foreign.output;
  EXPECT_TRUE(contains(foreign.output, "without run.json")) << foreign.output;
  EXPECT_EQ(readText(dir.path() / "notes.txt"), "mine");
  EXPECT_TRUE(leftovers(dir.path()).empty());
  // trace --out creates its directory (it wrote nothing before, and said no reason).
  const auto trace = runPenumbra("trace --pixel 16,16 --out " + (dir.path() / "new/t.json").string() + kSmall);
  EXPECT_EQ(trace.exitCode, 0) << trace.output;
  EXPECT_TRUE(json::parse(readText(dir.path() / "new/t.json")).contains("steps"));
}

// Case 5: an export over an earlier one replaces it as a whole: nothing old stays beside
// the new files; a killed export leaves the earlier one intact and its temporary removed
// by the next export.
TEST(CliReliability, ExportDirectoryIsATransaction) {
  const TempDirectory dir("penumbra_cli_transaction");
  const fs::path out = dir.path() / "export";
  ASSERT_EQ(runPenumbra("export --out " + out.string() + kSmall).exitCode, 0);
  std::ofstream(out / "stale.exr") << "from an earlier export";
  const std::string firstRun = readText(out / "run.json");
  ASSERT_EQ(runPenumbra("export --frame-key 7 --out " + out.string() + kSmall).exitCode, 0);
  EXPECT_FALSE(fs::exists(out / "stale.exr")) << "old and new files side by side";
  EXPECT_NE(readText(out / "run.json"), firstRun);
  const std::string secondRun = readText(out / "run.json");

  // Kill an export (SIGKILL) as soon as it starts writing its temporary directory.
  const fs::path temporaryPrefix = dir.path() / ".export.partial-";
  int killedWhileWriting = 0;
  for (int attempt = 0; attempt < 3 && killedWhileWriting == 0; ++attempt) {
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      const std::string binary = penumbraBinary();
      const std::string outArg = out.string();
      execl(binary.c_str(), binary.c_str(), "export", "--frame-key", "9", "--out", outArg.c_str(),
            "--width", "256", "--height", "256", static_cast<char*>(nullptr));
      _exit(127);
    }
    const fs::path temporary = temporaryPrefix.string() + std::to_string(child);
    const auto start = std::chrono::steady_clock::now();
    while (!fs::exists(temporary) && std::chrono::steady_clock::now() - start < std::chrono::seconds(60)) {
      int status = 0;
      if (waitpid(child, &status, WNOHANG) == child) break;  // finished before we saw it
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    if (fs::exists(temporary)) {
      kill(child, SIGKILL);
      ++killedWhileWriting;
    }
    int status = 0;
    waitpid(child, &status, 0);
    if (killedWhileWriting) {
      EXPECT_TRUE(WIFSIGNALED(status));
    }
  }
  ASSERT_EQ(killedWhileWriting, 1) << "never caught the export while writing";
  EXPECT_EQ(readText(out / "run.json"), secondRun) << "the earlier export was touched";
  EXPECT_FALSE(leftovers(dir.path()).empty()) << "SIGKILL leaves the temporary (nothing can run)";
  // The next export removes the dead one's temporary.
  ASSERT_EQ(runPenumbra("export --out " + out.string() + kSmall).exitCode, 0);
  EXPECT_TRUE(leftovers(dir.path()).empty()) << leftovers(dir.path()).front();
}

// Case 2: a light of size 1e30 with the reference on aborted inside Embree.
TEST(CliReliability, ExtremeScenesAreRefusedNotAborted) {
  const TempDirectory dir("penumbra_cli_extreme");
  json scene = groundAndPlateScene();
  scene["light"]["width"] = 1e30;
  const std::string path = dir.write("huge_light.json", scene.dump());
  const auto result = runPenumbra("export --scene " + path + " --set reference.enabled=true --out " +
                                  (dir.path() / "out").string() + kSmall);
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_TRUE(contains(result.output, "/light/width")) << result.output;
  EXPECT_TRUE(contains(result.output, "2e+06")) << result.output;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

// Case 6 on the command line: the light facing away from every occluder is warned about.
TEST(CliReliability, LightFacingAwayFromTheOccludersIsWarnedAbout) {
  const TempDirectory dir("penumbra_cli_away");
  json scene = groundAndPlateScene();
  scene["objects"][1]["ground"]["y"] = 5;  // the plate above a light that faces the ground
  const std::string path = dir.write("away.json", scene.dump());
  const auto result = runPenumbra("export --scene " + path + " --out " + (dir.path() / "out").string() + kSmall);
  EXPECT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "warning: the light faces away from every occluder")) << result.output;
}

// Case 7: messages.
TEST(CliReliability, MessagesAreShortAndSayWhy) {
  const TempDirectory dir("penumbra_cli_messages");
  const fs::path never = dir.path() / "never";
  const auto timeLimit = runPenumbra("bench --scene cube --out " + never.string() + " --time-limit -1");
  EXPECT_EQ(timeLimit.exitCode, 2);
  EXPECT_LT(timeLimit.output.size(), 300u) << timeLimit.output;
  EXPECT_TRUE(contains(timeLimit.output, "--time-limit")) << timeLimit.output;
  for (const char* value : {"0x4", "inf"}) {  // more spellings: tests/core/test_param_syntax.cpp
    const auto hex = runPenumbra("export --out " + never.string() + " --set 'trace.rays=" + value + "'");
    EXPECT_EQ(hex.exitCode, 2) << value << ": " << hex.output;
  }
  EXPECT_FALSE(fs::exists(never));
  const auto scenes = runPenumbra("bench-stages --scenes '' --out " + (never / "t.md").string());
  EXPECT_EQ(scenes.exitCode, 2) << scenes.output;
  EXPECT_TRUE(contains(scenes.output, "names no scene")) << scenes.output;
  EXPECT_FALSE(fs::exists(never));
}

// A method selected but disabled: composite.shadow=raster4d without raster4d.enabled gave a
// composite byte-identical to no shadow at all, exit 0, no word (so did error.method and
// error.against naming it). Refused, naming the fix; enabled, it runs.
TEST(CliReliability, ASelectedButDisabledMethodIsRefused) {
  const TempDirectory dir("penumbra_cli_disabled");
  for (const std::string& set : {std::string("composite.shadow=raster4d"), std::string("error.method=raster4d"),
                                 std::string("error.against=raster4d")}) {
    const auto result = runPenumbra("export --out " + (dir.path() / "x").string() + " --set " + set + kSmall);
    EXPECT_EQ(result.exitCode, 2) << set << "\n" << result.output;
    EXPECT_TRUE(contains(result.output, "which is disabled (raster4d.enabled=false)")) << result.output;
    EXPECT_TRUE(contains(result.output, "--set raster4d.enabled=true")) << result.output;
    EXPECT_FALSE(fs::exists(dir.path() / "x"));
  }
  const auto enabled = runPenumbra("export --out " + (dir.path() / "y").string() +
                                   " --set composite.shadow=raster4d --set raster4d.enabled=true --set raster4d.samples=8" + kSmall);
  EXPECT_EQ(enabled.exitCode, 0) << enabled.output;
}

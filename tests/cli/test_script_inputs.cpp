// Scripts, lessons and settings are inputs too (README "Scripts and lessons"): the output
// rule (io/output_path.h: nothing emptied or written outside its folder, a lesson's folder
// one transaction) and the reader rule (base/json_input.h: limits, FIFOs, messages), run as a
// user runs them. Most cases are refused before the window opens, so they take no time.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/command.h"
#include "support/refusal.h"
#include "support/temp_directory.h"
#include "support/window_test.h"

namespace fs = std::filesystem;

namespace {

// Every file under `directory`, relative, sorted (the whole tree as a listing to compare).
std::string listing(const fs::path& directory) {
  std::vector<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(directory))
    names.push_back(fs::relative(entry.path(), directory).string());
  std::sort(names.begin(), names.end());
  std::string text;
  for (const auto& name : names) text += name + "\n";
  return text;
}

CommandResult script(const fs::path& file, const std::string& arguments = "") {
  return runPenumbra("--script " + file.string() + " " + arguments);
}

// As runPenumbra, killed after 20 s (exit status 124): a FIFO must not hang the test.
CommandResult withTimeout(const std::string& arguments) {
  const std::string command = "timeout 20 " + penumbraBinary() + " " + arguments + " 2>&1";
  CommandResult result{-1, ""};
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  while (size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) result.output.append(buffer, n);
  const int status = pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

const char* kSmall = R"({"eye_size": [32, 32]}, {"set": {"light.resolution": 128}}, )";

}  // namespace

// 1. export_all emptied a directory it did not create (thesis.tex gone, exit 0).
TEST(ScriptInputs, ExportAllLeavesAForeignDirectoryAlone) {
  const TempDirectory dir("penumbra_script_export_all");
  const fs::path docs = dir.path() / "docs";
  fs::create_directories(docs);
  std::ofstream(docs / "thesis.tex") << "keep";
  const std::string file = dir.write("s.json", std::string("[") + kSmall + R"({"export_all": ")" +
                                                   docs.string() + R"("}])");
  const auto result = script(file);
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_TRUE(contains(result.output, "without run.json")) << result.output;
  EXPECT_EQ(readText(docs / "thesis.tex"), "keep");
  EXPECT_EQ(listing(docs), "thesis.tex\n");
}

// 2. Scripts and lessons wrote anywhere: "..", and absolute paths under an export folder.
TEST(ScriptInputs, PathsThatLeaveTheExportFolderAreRefusedBeforeTheWindowOpens) {
  const TempDirectory dir("penumbra_script_escapes");
  const fs::path out = dir.path() / "out", outside = dir.path() / "outside";
  fs::create_directories(outside);
  std::ofstream(outside / "old.png") << "old";
  const std::string lessonHead = R"([{"lesson": "t"}, )";
  const std::vector<std::string> escapes = {
      R"({"export_view": "../outside/old.png"})",
      R"({"export_view": ")" + (outside / "old.png").string() + R"("})",
      R"({"export_view": {"file": "a/../../outside/x.png"}})",
      R"({"screenshot": "../outside/s.png"})",
      R"({"screenshot": ")" + (outside / "s.png").string() + R"("})",
      R"({"export_all": "../outside"})",
      R"({"export_all": ")" + outside.string() + R"("})",
      R"({"save_settings": "../outside/old.png"})"};
  int refused = 0;
  for (size_t i = 0; i < escapes.size(); ++i) {
    const std::string& action = escapes[i];
    // Every escape in a lesson; two of them in a plain script with --export (same checks).
    for (const std::string& head : {lessonHead, std::string("[")}) {
      const bool lesson = head == lessonHead;
      if (!lesson && i % 4 != 0) continue;
      const std::string file = dir.write("e.json", head + action + "]");
      // A lesson always has its folder; a plain script has one with --export.
      const auto result = script(file, "--export " + out.string());
      EXPECT_EQ(result.exitCode, 2) << action << (lesson ? " (lesson)" : "") << "\n" << result.output;
      EXPECT_TRUE(contains(result.output, "'..'") || contains(result.output, "absolute path"))
          << result.output;
      refused += result.exitCode == 2;
    }
  }
  EXPECT_EQ(refused, 10);
  EXPECT_EQ(listing(outside), "old.png\n");
  EXPECT_EQ(readText(outside / "old.png"), "old");
  EXPECT_FALSE(fs::exists(out)) << listing(out);
  // ".." is refused in a plain script without an export folder too.
  const auto plain = script(dir.write("p.json", R"([{"save_settings": "x/../../s.json"}])"));
  EXPECT_EQ(plain.exitCode, 2) << plain.output;
}

// 2b. save_settings overwrote an unrelated file with settings JSON.
TEST(ScriptInputs, SaveSettingsReplacesOnlyASettingsFile) {
  REQUIRE_DISPLAY();
  const TempDirectory dir("penumbra_script_save_settings");
  const std::string notes = dir.write("notes.json", "{\"mine\": 1}\n");
  const auto refused = script(dir.write("s.json", std::string("[") + kSmall + R"({"save_settings": ")" +
                                                      notes + R"("}])"));
  EXPECT_EQ(refused.exitCode, 2) << refused.output;
  EXPECT_TRUE(contains(refused.output, "not a penumbra settings file")) << refused.output;
  EXPECT_EQ(readText(notes), "{\"mine\": 1}\n");
}

// 3. A lesson's folder is one transaction: a failing lesson leaves the previous export
//    whole; a folder that is not a lesson's export is refused; dead runs' leftovers go.
TEST(ScriptInputs, ALessonExportIsOneTransaction) {
  REQUIRE_DISPLAY();
  const TempDirectory dir("penumbra_lesson_transaction");
  const fs::path out = dir.path() / "out";
  const std::string good = dir.write(
      "good.json", std::string(R"([{"lesson": "t"}, )") + kSmall +
                       R"({"say": "one"}, {"export_view": "a.png"}, {"export_view": "b.png"}])");
  const auto first = runPenumbra("lesson " + good + " --export " + out.string());
  ASSERT_EQ(first.exitCode, 0) << first.output;
  const std::string before = listing(out), lessonMd = readText(out / "lesson.md");
  EXPECT_TRUE(contains(before, "a.png\n") && contains(before, "lesson.md\n")) << before;
  EXPECT_FALSE(contains(first.output, ".partial")) << "temporary paths shown: " << first.output;
  // A leftover of a killed run (its process long gone) is removed by the next start.
  fs::create_directories(dir.path() / ".out.partial-999999999" / "x");
  // The second lesson writes c.png, then fails: nothing of it may show.
  const std::string failing = dir.write(
      "failing.json", std::string(R"([{"lesson": "t"}, )") + kSmall +
                          R"({"export_view": "c.png"}, {"say": "{no_such_number}"}])");
  const auto second = runPenumbra("lesson " + failing + " --export " + out.string());
  EXPECT_EQ(second.exitCode, 2) << second.output;
  EXPECT_EQ(listing(out), before);
  EXPECT_EQ(readText(out / "lesson.md"), lessonMd);
  for (const auto& entry : fs::recursive_directory_iterator(dir.path()))
    EXPECT_FALSE(contains(entry.path().filename().string(), ".partial")) << entry.path();
  // A folder holding anything else is never replaced.
  const fs::path foreign = dir.path() / "foreign";
  fs::create_directories(foreign);
  std::ofstream(foreign / "thesis.tex") << "keep";
  const auto refused = runPenumbra("lesson " + good + " --export " + foreign.string());
  EXPECT_EQ(refused.exitCode, 2) << refused.output;
  EXPECT_TRUE(contains(refused.output, "without lesson.md")) << refused.output;
  EXPECT_EQ(listing(foreign), "thesis.tex\n");
}

// 4., 8. Deep nesting crashed (stack overflow); FIFOs hung; the limits are those of the
//    scene reader, with the same "<file>: <pointer>: <problem>" messages.
TEST(ScriptInputs, EveryJsonInputHasTheReadersLimits) {
  const TempDirectory dir("penumbra_script_limits");
  const std::string deep = dir.write("deep.json", std::string(100001, '[') + std::string(100001, ']'));
  for (const std::string& command : {"--script " + deep, "lesson " + deep, "--config " + deep + " --screenshot " +
                                     (dir.path() / "s.png").string()}) {
    const auto result = runPenumbra(command);
    EXPECT_EQ(result.exitCode, 2) << command << "\n" << result.output.substr(0, 2000);
    EXPECT_TRUE(contains(result.output, deep + ": /0/0/0/0")) << result.output.substr(0, 2000);
    EXPECT_TRUE(contains(result.output, "nested deeper than 64 levels")) << result.output.substr(0, 2000);
  }
  // A correctly typed deep argument (copied when the action runs).
  std::string views = "1";
  for (int i = 0; i < 100; ++i) views = "[" + views + "]";
  const auto typed = script(dir.write("typed.json", R"([{"settings": {"views": )" + views + "}}]"));
  EXPECT_EQ(typed.exitCode, 2) << typed.output.substr(0, 2000);
  EXPECT_TRUE(contains(typed.output, "nested deeper than 64 levels")) << typed.output.substr(0, 2000);
  // Keys given twice: the scene reader refuses them, so do the others.
  const auto twice = script(dir.write("twice.json", R"([{"wait": 1, "wait": 2}])"));
  EXPECT_EQ(twice.exitCode, 2) << twice.output;
  EXPECT_TRUE(contains(twice.output, "/0/wait: key given twice")) << twice.output;
  const auto settingsTwice = runPenumbra("--config " + dir.write("c.json", R"({"eye": "fit", "eye": [64, 64]})") +
                                         " --screenshot " + (dir.path() / "s.png").string());
  EXPECT_EQ(settingsTwice.exitCode, 2) << settingsTwice.output;
  EXPECT_TRUE(contains(settingsTwice.output, "/eye: key given twice")) << settingsTwice.output;
  // FIFOs, directories and devices: refused before reading, never waited on.
  const fs::path fifo = dir.path() / "f.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& command :
       {"--script " + fifo.string(), "lesson " + fifo.string(), "--config " + fifo.string() + " --screenshot " +
        (dir.path() / "s.png").string(), std::string("--script /dev/zero"), "--script " + dir.path().string(),
        "--scene " + fifo.string() + " --screenshot " + (dir.path() / "s.png").string()}) {
    const auto result = withTimeout(command);
    EXPECT_EQ(result.exitCode, 2) << command << "\n" << result.output;
    EXPECT_TRUE(contains(result.output, "not a regular file")) << command << "\n" << result.output;
    EXPECT_FALSE(contains(result.output, "watchdog")) << result.output;
  }
}

// 5., Messages: a long text, a long action name, control characters, the lesson prefix.
TEST(ScriptInputs, TextsAndNamesAreBoundedAndPlain) {
  const TempDirectory dir("penumbra_script_texts");
  const auto longSay = runPenumbra("lesson " + dir.write("say.json", R"([{"lesson": "t"}, {"say": ")" +
                                                                      std::string(26000, 'x') + R"("}])"));
  EXPECT_EQ(longSay.exitCode, 2) << longSay.output.substr(0, 1000);
  EXPECT_TRUE(contains(longSay.output, "/1/say: a string of 26000 bytes (at most 4096 bytes)"))
      << longSay.output.substr(0, 1000);
  EXPECT_EQ(longSay.output.rfind("penumbra lesson: ", 0), 0u) << "lesson errors say lesson: " << longSay.output;
  EXPECT_LT(longSay.output.size(), 1000u);
  for (const size_t length : {size_t(4000), size_t(30) << 20}) {
    const auto name = script(dir.write("name.json", "[{\"" + std::string(length, 'n') + "\": 1}]"));
    EXPECT_EQ(name.exitCode, 2);
    EXPECT_LT(name.output.size(), 2000u) << "the name echoed whole";
    EXPECT_TRUE(contains(name.output, length < 10000 ? "unknown action 'nnnn" : "at most 16 MiB"))
        << name.output.substr(0, 2000);
  }
  // Control characters in lesson texts never reach the terminal.
  REQUIRE_DISPLAY();
  const auto played = runPenumbra(
      "lesson " + dir.write("esc.json", std::string(R"([{"lesson": "t\u001b]0;x\u0007"}, )") + kSmall +
                                            R"({"say": "a\u001b[2Jb\u0007c\r\n\u009bd"}])") +
      " --export " + (dir.path() / "out").string());
  EXPECT_EQ(played.exitCode, 0) << played.output;
  EXPECT_TRUE(contains(played.output, "lesson step 1/1: a[2Jbc\nd")) << played.output;
  EXPECT_FALSE(contains(played.output, "\x1b") || contains(played.output, "\x07") ||
               contains(played.output, "\r") || contains(played.output, "\xc2\x9b"));
}

// 6., Range checks: every number an action converts is checked before the window opens.
TEST(ScriptInputs, NumericArgumentsOutOfRangeAreRefused) {
  const TempDirectory dir("penumbra_script_ranges");
  const std::pair<std::string, std::string> cases[] = {
      {R"({"pick": [1e300, -1e300]})", "/0/pick: script action 1 (pick): expected [a, b], numbers in [-1e+06, 1e+06]"},
      {R"({"wait": 9223372036854775807})", "expected an integer in [0, 100000]"},
      {R"({"wait": 18446744073709551615})", "expected an integer in [0, 100000]"},
      {R"({"level": 40})", "expected an integer in [0, 31]"},
      {R"({"camera_orbit": [1e300, 0]})", "numbers in [-1e+06, 1e+06]"},
      {R"({"eye_size": [1e300, 64]})", "numbers in [16, 8192]"},
      {R"({"select_ray": -1})", "expected an integer in [0, 65535]"},
      {R"({"view": 7})", "expected an integer in [0, 3]"},
      {R"({"zoom": 1e300})", "zoom factor in (0, 1e6]"},
      {R"({"camera_dolly": 0})", "number in [0.001, 1000]"},
      {R"({"range": [0, 1e39]})", "numbers in [-1e+30, 1e+30]"},
      {R"({"mouse": [0, 1e7]})", "numbers in [-1e+06, 1e+06]"},
      {R"({"drag": {"from": [0, 0], "to": [1, 1], "frames": "many"}})", "\"frames\": expected an integer in [1, 240]"},
      {R"({"drag": {"from": [0, 1e300], "to": [1, 1]}})", "\"from\": expected [a, b]"},
      {R"({"wheel": {"at": [0, 0], "amount": 1e300}})", "\"amount\": expected a number in [-100, 100]"},
      {R"({"ui_scale": 1e300})", "expected a number in (0, 1000]"}};
  for (const auto& [action, expected] : cases) {
    const auto result = script(dir.write("r.json", "[" + action + "]"));
    EXPECT_EQ(result.exitCode, 2) << action << "\n" << result.output;
    EXPECT_TRUE(contains(result.output, expected)) << action << "\n" << result.output;
  }
}

// 9. The window's --set of a disabled method (composite.shadow=raster4d, raster4d off) drew
// no shadow and said nothing. The command line refuses it (CliReliability); the window warns
// in its log panel and status line (the stage can be enabled there), naming the fix.
TEST(ScriptInputs, TheWindowWarnsWhenSetSelectsADisabledMethod) {
  const TempDirectory dir("penumbra_window_disabled");
  const std::string file = dir.write("s.json", std::string("[") + kSmall + R"({"print_log": "end"}])");
  const auto warned = script(file, "--set composite.shadow=raster4d");
  EXPECT_EQ(warned.exitCode, 0) << warned.output;
  std::istringstream lines(warned.output);
  bool logged = false;
  for (std::string line; std::getline(lines, line);)
    logged |= line.rfind("log end: ", 0) == 0 && contains(line, "warning  --set: composite.shadow=raster4d") &&
              contains(line, "which is disabled (raster4d.enabled=false)") &&
              contains(line, "add --set raster4d.enabled=true");
  EXPECT_TRUE(logged) << warned.output;
  const auto enabled = script(file, "--set composite.shadow=raster4d --set raster4d.enabled=true --set raster4d.samples=8");
  EXPECT_EQ(enabled.exitCode, 0) << enabled.output;
  EXPECT_FALSE(contains(enabled.output, "which is disabled")) << enabled.output;
}

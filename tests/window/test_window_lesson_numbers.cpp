// Numbers in a lesson's texts come from the run (lessons/README.md, "Numbers in texts"):
// a caption's {pixels:...}, {min:...}, {pct:a/b} and counters are the values this run's
// EXRs give when recomputed here; nothing is left unreplaced in lesson.md; an unknown
// placeholder or a malformed comparison stops the lesson with a message naming it.
// Every lesson's placeholders are of a known kind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "io/image_export.h"
#include "support/command.h"
#include "support/window_test.h"

namespace fs = std::filesystem;

namespace {

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The numbers after "KEY=" in `text`, as written.
std::string valueAfter(const std::string& text, const std::string& key) {
  const size_t at = text.find(key + "=");
  if (at == std::string::npos) return "";
  const size_t start = at + key.size() + 1;
  return text.substr(start, text.find_first_of(" ;\n`", start) - start);
}

const char* kSetup = R"([{"lesson": "numbers"}, {"scene": "cube"}, {"eye_size": [96, 72]},
  {"set": {"reference.enabled": true, "reference.samples": 4, "trace.rays": 2, "error.method": "trace"}},
  {"select_output": "error.signed"}, {"wait": 2},)";

}  // namespace

TEST(WindowLessonNumbers, CaptionsCarryTheRunsNumbersAndNothingIsLeftUnreplaced) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("lesson_numbers");
  const auto script = writeScript(dir, std::string(kSetup) + R"(
    {"say": "first text, pixels={pixels:error.signed<-0.02}"},
    {"keep": {"dark": "pixels:error.signed<-0.02", "all": "pixels:error.signed>=-2"}},
    {"export_view": {"file": "signed.exr"}},
    {"export_view": {"file": "signed.png", "caption": "dark={pixels:error.signed<-0.02} share={share:error.signed<-0.02} min={min:error.signed} max={max:error.signed} pct={pct:dark/all} rmse={error.rmse}"}},
    {"say": "the end, ratio={ratio:dark/all}"}])");
  const fs::path out = dir / "export";  // a lesson replaces only a folder of its own
  const auto result = runPenumbra("lesson " + script.string() + " --export " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  int w = 0, h = 0;
  std::vector<std::string> names;
  const std::vector<float> error = readExr(out / "signed.exr", w, h, names);
  ASSERT_EQ(w * h, 96 * 72);
  int dark = 0;
  float low = 1e9f, high = -1e9f;
  for (float v : error) {
    dark += v < -0.02f;
    low = std::min(low, v);
    high = std::max(high, v);
  }
  ASSERT_GT(dark, 0) << "the test needs some too-dark pixels";
  const std::string md = readText(out / "lesson.md");
  EXPECT_EQ(md.find('{'), std::string::npos) << md;  // every placeholder filled in
  EXPECT_EQ(valueAfter(md, "dark"), std::to_string(dark)) << md;
  EXPECT_EQ(valueAfter(md, "pixels"), std::to_string(dark)) << md;
  EXPECT_NEAR(std::stod(valueAfter(md, "share")), 100.0 * dark / (w * h), 0.51) << md;
  EXPECT_NEAR(std::stod(valueAfter(md, "pct")), 100.0 * dark / (w * h), 0.51) << md;
  EXPECT_NEAR(std::stod(valueAfter(md, "ratio")), double(dark) / (w * h), 1e-3) << md;
  EXPECT_NEAR(std::stod(valueAfter(md, "min")), low, 1e-3 * std::abs(low)) << md;
  EXPECT_NEAR(std::stod(valueAfter(md, "max")), high, 1e-3 * std::abs(high) + 1e-6) << md;
  EXPECT_FALSE(valueAfter(md, "rmse").empty()) << md;
  // The sheet's caption is the same text (lesson.md lists the panels' captions).
  EXPECT_NE(md.find("`signed.png`: dark=" + std::to_string(dark)), std::string::npos) << md;
}

TEST(WindowLessonNumbers, AnUnknownOrMalformedPlaceholderStopsTheLessonWithItsName) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("lesson_numbers_bad");
  for (const std::string& bad : {std::string("{trace.noSuchCounter}"), std::string("{pixels:error.signed~3}"),
                                 std::string("{min:nostage.output}"), std::string("{pct:error.rmse}")}) {
    const auto script = writeScript(dir, std::string(kSetup) + R"({"say": "number )" + bad + R"("},
      {"export_view": {"file": "x.png", "caption": "x"}}])");
    const auto result = runPenumbra("lesson " + script.string() + " --export " + (dir / "export").string());
    EXPECT_NE(result.exitCode, 0) << bad << "\n" << result.output;
    EXPECT_NE(result.output.find(bad), std::string::npos) << bad << "\n" << result.output;
  }
}

// Without playing them: every {...} in every lesson is one of the documented kinds.
TEST(LessonNumbers, EveryLessonsPlaceholdersAreOfAKnownKind) {
  const std::regex placeholder(R"(\{([^{}"]*)\})");
  const std::regex known(
      R"(^(ms|ms:[a-z0-9_+]+|crop\.[A-Za-z]+|(pixels|share):[a-z0-9_]+\.[A-Za-z0-9_]+(<|>|<=|>=|==)-?[0-9.]+|)"
      R"((min|max|p99|pick):[a-z0-9_]+\.[A-Za-z0-9_]+|temporal(_pixel|_spread)?:[a-z0-9_]+|(pct|ratio):[A-Za-z0-9_.:]+/[A-Za-z0-9_.:]+|[A-Za-z0-9_.]+)$)");
  int count = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(PENUMBRA_SOURCE_DIR) / "lessons")) {
    if (entry.path().extension() != ".json") continue;
    const std::string text = readText(entry.path());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), placeholder); it != std::sregex_iterator(); ++it) {
      ++count;
      EXPECT_TRUE(std::regex_match((*it)[1].str(), known)) << entry.path().filename() << ": " << (*it)[0];
    }
  }
  EXPECT_GT(count, 50);
}

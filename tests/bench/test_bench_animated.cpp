// `penumbra bench --preset animated` (app/bench/bench_animated.h): a tiny run on the toys over
// its first 3 frames, through the binary: the tables' columns and rows (results.csv with its
// loop columns, loop.csv one row per frame and configuration, results.md's loop tables and
// Wang et al.'s comparison), the reference's BVH rebuilt each frame and its time reported
// apart. No time is asserted: only that each is a finite, positive number where one exists.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "bench/bench_configs.h"
#include "bench/bench_json.h"
#include "bench/bench_output.h"
#include "core/pipeline.h"
#include "scene/scene_animated.h"
#include "scene/scene_builtin.h"
#include "support/command.h"
#include "support/read_csv.h"
#include "support/temp_directory.h"

namespace {

size_t column(const std::vector<std::string>& header, const std::string& name) {
  return size_t(std::find(header.begin(), header.end(), name) - header.begin());
}

std::string readText(const std::filesystem::path& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace

TEST(BenchAnimated, PlanCoversTheWholeCycleAtTheFrameRate) {
  std::vector<std::string> warnings;
  const Scene toys = makeAnimatedScene("toys", warnings);
  const Pipeline graph;
  BenchPlanOptions options{"animated", {}, 0, 0};
  options.fps = 2;
  const auto plan = makeBenchPlan(toys, options, graph);
  ASSERT_EQ(plan.size(), 1u);
  ASSERT_TRUE(plan[0].animated());
  // The toys loop every 4 s: 8 frames at 2 fps, t = 0, 0.5, ..., 3.5.
  ASSERT_EQ(plan[0].loopTimes.size(), size_t(std::lround(toys.animation.duration * 2)));
  EXPECT_DOUBLE_EQ(plan[0].loopTimes[1], 0.5);
  EXPECT_TRUE(plan[0].scene.animation.empty());  // the error frame's pose
  EXPECT_FALSE(plan[0].rest->animation.empty());
  // The reference rebuilds its BVH every frame, at 1x1 .. 8x8 and at raster4d's 32x32.
  std::set<int> samples;
  for (const BenchConfig& config : plan[0].configs)
    if (config.referenceSamples > 0) {
      EXPECT_TRUE(config.rebuildBvh) << config.label;
      samples.insert(config.referenceSamples);
    }
  EXPECT_EQ(samples, (std::set<int>{1, 2, 4, 8, 32}));
  EXPECT_EQ(graph.param("raster4d.samples").asInt(), 32);  // Wang et al.'s, compared at equal m
  options.loopFrames = 3;
  EXPECT_EQ(makeBenchPlan(toys, options, graph)[0].loopTimes.size(), 3u);
  // A static scene has no loop to time.
  EXPECT_THROW(makeBenchPlan(makeBuiltinScene("cube"), options, graph), std::invalid_argument);
}

TEST(BenchAnimated, TinyToysRunWritesThePerFrameTables) {
  const TempDirectory scratch("penumbra-bench-animated");
  const auto out = scratch.path() / "out", cache = scratch.path() / "cache";
  setenv("PENUMBRA_CACHE", cache.c_str(), 1);  // inherited by the command
  const CommandResult result = runPenumbra(
      "bench --scene toys --preset animated --width 48 --height 32 --fps 4 --loop-frames 3 "
      "--reference-samples 4 --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;

  // results.csv: one row per configuration, with the loop's columns.
  const auto rows = readCsv(out / "results.csv");
  ASSERT_GE(rows.size(), 2u);
  EXPECT_EQ(rows[0], benchCsvColumns());
  std::vector<std::string> warnings;
  const Scene toys = makeAnimatedScene("toys", warnings);
  BenchPlanOptions options{"animated", {}, 48, 32};
  options.fps = 4, options.loopFrames = 3;
  const auto plan = makeBenchPlan(toys, options, Pipeline{});
  const size_t configs = plan[0].configs.size();
  ASSERT_EQ(rows.size(), 1 + configs) << result.output;
  const auto& h = rows[0];
  size_t references = 0;
  for (size_t r = 1; r < rows.size(); ++r) {
    EXPECT_EQ(rows[r][column(h, "loop_frames")], "3") << rows[r][column(h, "config")];
    EXPECT_EQ(rows[r][column(h, "frames")], "3");
    EXPECT_GT(std::stod(rows[r][column(h, "ms_median")]), 0);
    EXPECT_GE(std::stod(rows[r][column(h, "ms_max")]), std::stod(rows[r][column(h, "ms_median")]));
    const double worstAt = std::stod(rows[r][column(h, "worst_frame_time")]);
    EXPECT_TRUE(worstAt == 0 || worstAt == 0.25 || worstAt == 0.5) << worstAt;
    if (rows[r][column(h, "method")] == "reference") {
      ++references;
      EXPECT_GT(std::stod(rows[r][column(h, "bvh_ms_median")]), 0);  // rebuilt, reported apart
      EXPECT_NE(rows[r][column(h, "timed_stages")].find("bvh_build"), std::string::npos);
    }
  }
  EXPECT_EQ(references, 5u);

  // loop.csv: one row per frame and configuration.
  const auto loop = readCsv(out / "loop.csv");
  ASSERT_EQ(loop.size(), 1 + 3 * configs);
  EXPECT_EQ(loop[0], (std::vector<std::string>{"setup", "config", "method", "frame", "time", "ms",
                                               "bvh_ms", "pose_upload_ms"}));
  for (size_t r = 1; r < loop.size(); ++r) {
    EXPECT_GT(std::stod(loop[r][5]), 0);
    EXPECT_GT(std::stod(loop[r][7]), 0);
    if (loop[r][2] == "reference") EXPECT_GT(std::stod(loop[r][6]), 0);
    else EXPECT_EQ(loop[r][6], "");
  }

  // results.md: the loop table (a row per configuration), Wang's comparison at 32x32, and
  // every frame's row.
  const std::string md = readText(out / "results.md");
  EXPECT_NE(md.find("### Loop: 3 frames at 4.00 fps"), std::string::npos) << md;
  EXPECT_NE(md.find("| 32x32 | "), std::string::npos) << md;  // raster4d against reference 32x32
  for (const BenchConfig& config : plan[0].configs)
    EXPECT_NE(md.find("| " + config.label + " | "), std::string::npos) << config.label;
  for (const char* frame : {"| 0 | 0.000 | ", "| 1 | 0.250 | ", "| 2 | 0.500 | "})
    EXPECT_NE(md.find(frame), std::string::npos) << frame;
  for (const char* chart : {"speed_vs_error.png", "frame_times.png"})
    EXPECT_TRUE(std::filesystem::exists(out / chart)) << chart;

  // results.json: the loop's arrays per result, read back.
  BenchRunInfo info;
  std::vector<BenchSetupInfo> setups;
  std::vector<BenchResult> results;
  ASSERT_EQ(parseBenchJson(readText(out / "results.json"), info, setups, results), "");
  ASSERT_EQ(results.size(), configs);
  EXPECT_EQ(setups[0].loopTimes.size(), 3u);
  EXPECT_EQ(setups[0].poseMs.size(), 3u);
  for (const BenchResult& r : results) {
    EXPECT_EQ(r.loopMs.size(), 3u) << r.label;
    EXPECT_EQ(r.loopBvhMs.size(), r.method == "reference" ? 3u : 0u) << r.label;
  }
}

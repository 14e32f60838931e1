// The window's live speed-against-error run (app/bench/live_bench.h): stepped to the end it
// measures every configuration of the preset plus the window's own, the window's own is the
// one matched as "current", only while the parameters stay; cancel keeps what is complete.
#include <gtest/gtest.h>

#include <algorithm>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <thread>

#include "bench/live_bench.h"
#include "core/pipeline.h"
#include "scene/scene_builtin.h"
#include "support/gl_test.h"
#include "support/temp_directory.h"

namespace {

int stepToTheEnd(LiveBench& bench) {
  int steps = 0;
  while (bench.running() && steps < 100000) {
    bench.step();
    ++steps;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));  // the reference's thread
  }
  return steps;
}

}  // namespace

// "current" is measured with the preset's error.pixels (one metric per chart), else with the
// window's.
TEST(LiveBench, CurrentCountsThePixelsThePresetCounts) {
  const Scene plate = makeBuiltinScene("plate");
  Pipeline window;
  const auto pixelsOf = [](const BenchConfig& config) {
    std::string last;
    for (const std::string& set : config.sets)
      if (set.rfind("error.pixels=", 0) == 0) last = set;
    return last;
  };
  const auto atty = makeBenchPlan(plate, {"atty-4.2", {}, 0, 0}, window);
  const auto minimal = makeBenchPlan(plate, {"minimal", {}, 0, 0}, window);
  EXPECT_EQ(pixelsOf(currentConfig(window, atty[0].configs)), "error.pixels=receivers");
  EXPECT_EQ(pixelsOf(currentConfig(window, minimal[0].configs)), "error.pixels=all");
  ASSERT_EQ(window.set("error.pixels=receivers"), "");
  EXPECT_EQ(pixelsOf(currentConfig(window, minimal[0].configs)), "error.pixels=receivers");
  EXPECT_EQ(pixelsOf(currentConfig(window)), "error.pixels=receivers");
}

TEST(LiveBench, MeasuresThePresetAndTheCurrentConfiguration) {
  const TempDirectory cache("penumbra-live-bench");
  setenv("PENUMBRA_CACHE", cache.path().c_str(), 1);
  headlessContext();
  const Scene plate = makeBuiltinScene("plate");
  Pipeline window;  // the window's parameters: a configuration the preset does not have
  ASSERT_EQ(window.set("trace.rays=3"), "");
  ASSERT_EQ(window.set("composite.shadow=filter"), "");
  LiveBench bench;
  LiveBenchOptions options;
  options.preset = "minimal";
  options.width = 48, options.height = 32;
  options.frames = 2, options.warmup = 1, options.referenceSamples = 2;
  bench.start(plate, window, options);
  EXPECT_TRUE(bench.running());
  EXPECT_EQ(bench.fingerprint(), sceneFingerprint(plate));
  const int steps = stepToTheEnd(bench);
  ASSERT_FALSE(bench.running()) << steps << " steps: " << bench.status();
  EXPECT_FLOAT_EQ(bench.progress(), 1.0f);
  const std::vector<BenchResult> results = bench.results();
  // every method but the Monte Carlo ones at its defaults, hierarchical 2x2, the reference
  // at 1x1 .. 8x8, current
  ASSERT_EQ(results.size(), Pipeline{}.methods().size() - 2 + 2 + 4);
  EXPECT_EQ(std::count_if(results.begin(), results.end(),
                          [](const BenchResult& r) { return r.method == "reference"; }), 4);
  for (const BenchResult& r : results) {
    EXPECT_EQ(r.frames, 2) << r.label;
    EXPECT_GT(r.msMedian, 0) << r.label;
    EXPECT_TRUE(std::isfinite(r.error.meanAbsInShadow)) << r.label;
    EXPECT_GT(r.error.pixels, 0u) << r.label;
  }
  EXPECT_EQ(results.back().family, "current");
  EXPECT_EQ(matchingResult(results, window), int(results.size()) - 1);
  ASSERT_EQ(window.set("trace.rays=4"), "");  // changed since: not measured
  EXPECT_EQ(matchingResult(results, window), -1);
  // The preset's hierarchical 2x2 map 512, two layers, over the N-buffer (the window's
  // defaults are `auto`).
  ASSERT_EQ(window.set("trace.rays=2"), "");
  ASSERT_EQ(window.set("trace.hierarchy=nbuffer"), "");
  ASSERT_EQ(window.set("light.resolution=512"), "");
  ASSERT_EQ(window.set("light.layers=two"), "");
  const int match = matchingResult(results, window);
  ASSERT_GE(match, 0);
  EXPECT_EQ(results[size_t(match)].params.at("trace.rays"), "2");

  // Cancel while the second configuration is measured: the first one remains, complete,
  // and nothing runs on.
  bench.start(plate, window, options);
  while (bench.running() && bench.results().size() < 2) bench.step();
  bench.cancel();
  EXPECT_FALSE(bench.running());
  ASSERT_EQ(bench.results().size(), 1u);
  EXPECT_EQ(bench.results()[0].frames, 2);
  EXPECT_FALSE(bench.step());
}

// The speed-vs-error panel's pure parts (app/window/panels/ui_speed_error.h,
// app/bench/live_bench.h, app/bench/bench_json.h): results.json read back as written, the
// Pareto frontier against a brute-force dominance check, the match of the current pipeline
// parameters, and the scene fingerprint that keeps another view's points from being
// "current". No window needed.
#include <gtest/gtest.h>

#include <algorithm>

#include "bench/bench_json.h"
#include "bench/live_bench.h"
#include "bench/pareto.h"
#include "core/pipeline.h"
#include "scene/scene_builtin.h"
#include "window/panels/ui_speed_error.h"

namespace {

// A result as `penumbra bench` records it: the method and every parameter of its stages
// after the configuration's sets (no GL: nothing is run).
BenchResult resultOf(const std::vector<std::string>& sets, double ms, double error) {
  Pipeline pipeline;
  for (const std::string& set : sets) EXPECT_EQ(pipeline.set(set), "") << set;
  const BenchConfig config = currentConfig(pipeline);
  BenchResult r;
  r.label = config.label;
  r.method = config.method;
  for (const std::string& stage : pipeline.dependencies({pipeline.methodOutput(r.method)}))
    for (const Param& param : pipeline.stage(stage).params())
      r.params[stage + "." + param.key] = param.toString();
  r.msMedian = ms;
  r.error.meanAbsInShadow = error;
  r.frames = 3;
  return r;
}

}  // namespace

TEST(SpeedErrorPanel, ResultsJsonReadsBackWhatWasWritten) {
  BenchRunInfo info;
  info.scene = "cube";
  info.preset = "minimal";
  info.frames = 10;
  std::vector<BenchResult> results = {
      resultOf({"composite.shadow=hard_shadow"}, 2, 0.2),
      resultOf({"composite.shadow=filter", "trace.rays=2"}, 8.5, 0.05)};
  results[1].stages = {"light", "trace"};
  results[1].stageMs = {{"light", 0.5}, {"trace", 8}};
  results[1].counters = {{"trace.fetchesPerRay", 4.9}};
  results[1].pareto = true;
  BenchSetupInfo setup;
  setup.label = "cube, 256x256";
  setup.width = setup.height = 256;
  const std::string text = benchJson(info, {setup}, results);
  BenchRunInfo readInfo;
  std::vector<BenchSetupInfo> setups;
  std::vector<BenchResult> read;
  ASSERT_EQ(parseBenchJson(text, readInfo, setups, read), "");
  ASSERT_EQ(read.size(), 2u);
  ASSERT_EQ(setups.size(), 1u);
  EXPECT_EQ(setups[0].label, "cube, 256x256");
  EXPECT_EQ(readInfo.frames, 10);
  EXPECT_EQ(read[1].method, "filter");
  EXPECT_EQ(read[1].params, results[1].params);
  EXPECT_EQ(read[1].stages, results[1].stages);
  EXPECT_DOUBLE_EQ(read[1].stageMs.at("trace"), 8);
  EXPECT_DOUBLE_EQ(read[1].counter("trace.fetchesPerRay"), 4.9);
  EXPECT_DOUBLE_EQ(read[1].msMedian, 8.5);
  EXPECT_DOUBLE_EQ(read[1].error.meanAbsInShadow, 0.05);
  EXPECT_TRUE(read[1].pareto);
  EXPECT_NE(parseBenchJson("{\"a\": 1}", readInfo, setups, read), "");  // not a bench file
  EXPECT_NE(parseBenchJson("not json", readInfo, setups, read), "");
}

TEST(SpeedErrorPanel, FrontierIsExactlyTheNonDominatedPoints) {
  const double data[][2] = {{1, 0.5}, {2, 0.3}, {3, 0.4}, {4, 0.1}, {5, 0.1}, {2.5, 0.3}, {10, 0.01}, {0.5, 0.9}};
  std::vector<double> ms, error;
  for (auto& d : data) ms.push_back(d[0]), error.push_back(d[1]);
  const std::vector<bool> frontier = paretoFrontier(ms, error);
  size_t count = 0;
  for (size_t i = 0; i < ms.size(); ++i) {
    bool dominated = false;  // brute force: some other point no worse in both, better in one
    for (size_t j = 0; j < ms.size(); ++j)
      dominated |= j != i && ms[j] <= ms[i] && error[j] <= error[i] &&
                   (ms[j] < ms[i] || error[j] < error[i]);
    EXPECT_EQ(bool(frontier[i]), !dominated) << "point " << i;
    count += frontier[i];
  }
  EXPECT_EQ(count, 5u);  // 0.5, 1, 2, 4, 10 ms
}

TEST(SpeedErrorPanel, MatchesTheCurrentPipelineParameters) {
  const std::vector<BenchResult> points = {
      // The light's parameters matter to every method (fixed here: their default is auto).
      resultOf({"composite.shadow=hard_shadow", "light.layers=two", "light.resolution=512"}, 2, 0.2),
      resultOf({"composite.shadow=filter", "trace.search=hierarchical", "light.layers=two",
                "trace.rays=2", "light.resolution=512"}, 8, 0.05),
      resultOf({"composite.shadow=filter", "trace.search=hierarchical", "light.layers=two",
                "trace.rays=3", "light.resolution=512"}, 12, 0.03)};
  Pipeline pipeline;
  for (const char* s : {"composite.shadow=filter", "trace.search=hierarchical", "light.layers=two",
                        "trace.rays=3", "light.resolution=512", "trace.deferred=true",
                        "filter.enabled=true"})
    ASSERT_EQ(pipeline.set(s), "") << s;
  EXPECT_EQ(matchingResult(points, pipeline), 2);
  ASSERT_EQ(pipeline.set("trace.deferred=false"), "");
  EXPECT_EQ(matchingResult(points, pipeline), -1);  // no exact match
  ASSERT_EQ(pipeline.set("composite.shadow=hard_shadow"), "");
  EXPECT_EQ(matchingResult(points, pipeline), 0);  // trace's parameters do not matter to it
  ASSERT_EQ(pipeline.set("hard_shadow.offset=0.05"), "");
  EXPECT_EQ(matchingResult(points, pipeline), -1);
}

TEST(SpeedErrorPanel, SceneFingerprintFollowsGeometryLightAndCamera) {
  const Scene cube = makeBuiltinScene("cube");
  EXPECT_EQ(sceneFingerprint(cube), sceneFingerprint(makeBuiltinScene("cube")));
  EXPECT_NE(sceneFingerprint(cube), sceneFingerprint(makeBuiltinScene("plate")));
  Scene moved = cube;
  moved.camera.position.x += 0.01f;
  EXPECT_NE(sceneFingerprint(moved), sceneFingerprint(cube));
  Scene lit = cube;
  lit.light.width *= 2;
  EXPECT_NE(sceneFingerprint(lit), sceneFingerprint(cube));
}

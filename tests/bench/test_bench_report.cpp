// `penumbra bench` (app/bench/bench_*.h, app/bench/plot.h): a tiny real run through the binary,
// its CSV's columns and numbers and its results.json, the refusal when the reference would
// take too long, the Pareto frontier, the setup modifiers of the presets, and the charts
// (cairo) as PNG with text, SVG and PDF.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>

#include <algorithm>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "bench/bench_configs.h"
#include "bench/bench_json.h"
#include "bench/bench_measure.h"
#include "bench/bench_output.h"
#include "bench/pareto.h"
#include "bench/plot.h"
#include "core/pipeline.h"
#include "scene/light_frame.h"
#include "scene/scene_builtin.h"
#include "support/command.h"
#include "support/read_csv.h"
#include "support/temp_directory.h"

namespace {

glm::vec3 occluderCentre(const Scene& scene) {
  const Bounds b = scene.bounds(true);
  return 0.5f * (b.min + b.max);
}

}  // namespace

TEST(BenchReport, TinyRunWritesTheExpectedColumnsAndFiniteNumbers) {
  const TempDirectory scratch("penumbra-bench-tiny");
  const auto out = scratch.path() / "out", cache = scratch.path() / "cache";
  setenv("PENUMBRA_CACHE", cache.c_str(), 1);  // inherited by the command
  const CommandResult result = runPenumbra(
      "bench --scene plate --preset minimal --sweep trace.rays=1,2 --width 64 --height 48 "
      "--frames 2 --warmup 1 --reference-samples 4 --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("references: 1 to compute"), std::string::npos) << result.output;
  ASSERT_TRUE(std::filesystem::exists(out / "results.csv")) << result.output;
  const auto rows = readCsv(out / "results.csv");
  // header + every method but the Monte Carlo ones at its defaults + hierarchical x 2 rays
  // + the reference as a method at 1x1, 2x2, 4x4, 8x8 (not swept: it does not trace)
  const size_t others = Pipeline{}.methods().size() - 2;
  ASSERT_EQ(rows.size(), 1u + others + 2u + 4u) << result.output;
  EXPECT_EQ(rows[0], benchCsvColumns());
  const std::vector<std::string> numeric = {"ms_median", "ms_min", "ms_max", "shadow_map",
                                            "rmse", "max_error", "mean_abs_error_in_shadow",
                                            "p99_abs_error", "mean_signed_error", "pixels"};
  for (size_t r = 1; r < rows.size(); ++r) {
    ASSERT_EQ(rows[r].size(), rows[0].size());
    for (const std::string& column : numeric) {
      const size_t c = size_t(std::find(rows[0].begin(), rows[0].end(), column) - rows[0].begin());
      const double value = std::stod(rows[r][c]);
      EXPECT_TRUE(std::isfinite(value) && value >= -1) << column << " row " << r;
    }
    const size_t ms = size_t(std::find(rows[0].begin(), rows[0].end(), "ms_median") - rows[0].begin());
    EXPECT_GT(std::stod(rows[r][ms]), 0);
  }
  EXPECT_EQ(rows[1][7], "hard_shadow");
  const size_t sets = size_t(std::find(rows[0].begin(), rows[0].end(), "sets") - rows[0].begin());
  EXPECT_NE(rows[1 + others][sets].find("trace.rays=1"), std::string::npos);  // the swept rows
  EXPECT_NE(rows[2 + others][sets].find("trace.rays=2"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(out / "results.md"));
  for (const char* extension : {".png", ".svg", ".pdf"})
    EXPECT_TRUE(std::filesystem::exists(out / (std::string("speed_vs_error") + extension))) << extension;

  // results.json holds the same rows, and each method's time covers exactly the stages its
  // visibility depends on in the graph.
  std::ifstream json(out / "results.json");
  std::stringstream text;
  text << json.rdbuf();
  BenchRunInfo info;
  std::vector<BenchSetupInfo> setups;
  std::vector<BenchResult> results;
  ASSERT_EQ(parseBenchJson(text.str(), info, setups, results), "");
  ASSERT_EQ(results.size(), rows.size() - 1);
  EXPECT_EQ(info.scene, "plate");
  const Pipeline graph;
  for (const BenchResult& r : results) {
    if (r.method == "reference") {  // the stages its rays need, its read-back and its trace
      std::vector<std::string> expected = graph.dependencies({"reference.visibility"});
      expected.erase(std::find(expected.begin(), expected.end(), "reference"));
      expected.push_back("readback");
      expected.push_back("embree_trace");
      EXPECT_EQ(r.stages, expected) << r.label;
      EXPECT_GT(r.bvhMsMedian, 0) << r.label;  // built once, reported apart
    } else {
      EXPECT_EQ(r.stages, graph.dependencies({graph.methodOutput(r.method)})) << r.label;
    }
    double sum = 0;
    for (const std::string& stage : r.stages) {
      ASSERT_TRUE(r.stageMs.count(stage)) << r.label << " " << stage;
      sum += r.stageMs.at(stage);
    }
    EXPECT_GT(sum, 0) << r.label;
    EXPECT_TRUE(std::isfinite(r.error.meanAbsInShadow));
  }
  EXPECT_EQ(results[others + 1].params.at("trace.rays"), "2");
  EXPECT_EQ(results[0].params.count("trace.rays"), 0u);  // the hard shadow does not trace
}

TEST(BenchReport, RefusesWhenTheReferenceWouldExceedTheTimeLimit) {
  const TempDirectory scratch("penumbra-bench-refuse");
  const auto out = scratch.path() / "out", cache = scratch.path() / "cache";
  setenv("PENUMBRA_CACHE", cache.c_str(), 1);  // nothing cached: the estimate decides
  const CommandResult result = runPenumbra(
      "bench --scene plate --preset minimal --width 64 --height 48 --frames 1 "
      "--reference-samples 64 --time-limit 0.000001 --out " + out.string());
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("refusing to start"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(out / "results.csv"));
}

TEST(BenchReport, UnknownPresetAndBadSweepAreRefused) {
  const TempDirectory scratch("penumbra-bench-bad");
  const std::string out = (scratch.path() / "out").string();
  CommandResult result = runPenumbra("bench --scene plate --preset nope --out " + out);
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.output.find("thesis-table-4.1"), std::string::npos) << result.output;
  result = runPenumbra("bench --scene plate --sweep trace.rays=1,99 --out " + out);
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.output.find("trace.rays"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(BenchPlan, PresetsAndSweepsHaveTheDocumentedShape) {
  const Scene plate = makeBuiltinScene("plate");
  const Pipeline graph;
  const size_t others = graph.methods().size() - 2;  // every method but trace and filter
  const auto thesis = makeBenchPlan(plate, {"thesis-table-4.1", {}, 0, 0}, graph);
  ASSERT_EQ(thesis.size(), 3u);  // map sweep at 512x384, then 400x300 and 640x512
  EXPECT_EQ(thesis[0].configs.size(), others + 6u * 3u + 4u);  // + the reference at 4 sizes
  EXPECT_EQ(thesis[1].width, 400);
  EXPECT_EQ(thesis[2].height, 512);
  const auto atty = makeBenchPlan(plate, {"atty-4.2", {}, 0, 0}, graph);
  EXPECT_EQ(atty.size(), 1u + 6u + 7u + 5u);
  // Atty et al. measure their method in one and two passes on every curve, its own maps at
  // the swept size (Fig. 17's x axis); every other method once per map size.
  for (const BenchSetup& setup : atty) {
    const size_t maps = setup.axis == "map" ? 7u : 1u;
    // ssm x 2, MC x 3; the map sweep's scatter also has the reference at 4 sample counts
    EXPECT_EQ(setup.configs.size(), maps * (others + 1u + 3u) + (maps > 1 ? 4u : 0u)) << setup.label;
    std::map<std::string, int> ssmPasses;
    for (const BenchConfig& config : setup.configs) {
      if (config.method != "ssm") continue;
      const auto has = [&](const std::string& set) {
        return std::find(config.sets.begin(), config.sets.end(), set) != config.sets.end();
      };
      const std::string map = config.label.substr(config.label.rfind(' ') + 1);
      EXPECT_TRUE(has("ssm.resolution=" + map) && has("light.resolution=" + map)) << config.label;
      EXPECT_TRUE(has("ssm.passes=one") != has("ssm.passes=two")) << config.label;
      ++ssmPasses[config.family];
    }
    EXPECT_EQ(ssmPasses["ssm one pass"], int(maps)) << setup.label;
    EXPECT_EQ(ssmPasses["ssm two passes"], int(maps)) << setup.label;
    // The paper's metric: the receivers' pixels only (§4.2.1), in every configuration.
    for (const BenchConfig& config : setup.configs)
      EXPECT_EQ(std::count(config.sets.begin(), config.sets.end(), "error.pixels=receivers"), 1)
          << config.label;
  }
  for (const BenchSetup& setup : thesis)
    for (const BenchConfig& config : setup.configs)
      for (const std::string& set : config.sets)
        EXPECT_EQ(set.rfind("error.pixels", 0), std::string::npos) << set;
  const auto swept = makeBenchPlan(plate, {"minimal", {"eye.size=32x32,64x48", "light.resolution=128,256"}, 0, 0}, graph);
  ASSERT_EQ(swept.size(), 2u);
  EXPECT_EQ(swept[1].width, 64);
  // Every method reads the light stage, so each is swept over both resolutions.
  // The reference reads no light.resolution: once.
  EXPECT_EQ(swept[0].configs.size(), 2u * (1u + others) + 4u);
  EXPECT_THROW(makeBenchPlan(plate, {"minimal", {"scene.vertical=2"}, 0, 0}, graph), std::invalid_argument);
  // The default preset measures `auto` (docs/accuracy.md) beside the fixed configurations; its
  // assignments apply and leave map, layers and rays automatic.
  const auto defaults = makeBenchPlan(plate, {"default", {}, 0, 0}, graph);
  const auto automatic = std::find_if(defaults[0].configs.begin(), defaults[0].configs.end(),
                                      [](const BenchConfig& c) { return c.label == "hierarchical auto"; });
  ASSERT_NE(automatic, defaults[0].configs.end());
  Pipeline measured;
  EXPECT_EQ(applySets(measured, automatic->sets), "");
  for (const char* key : {"light.resolution", "light.layers", "trace.rays"})
    EXPECT_TRUE(measured.param(key).automatic) << key;
}

// Oracles from the plate's geometry: ground at y = 0, light 1 x 1 at y = 3 facing down.
TEST(BenchPlan, SetupModifiersMoveTheOccludersWhereTheyClaim) {
  Scene plate = makeBuiltinScene("plate");
  placeOccludersVertically(plate, 0.5);  // the plate has no thickness: halfway is y = 1.5
  EXPECT_NEAR(occluderCentre(plate).y, 1.5f, 1e-5f);
  placeOccludersVertically(plate, 0.0);
  EXPECT_NEAR(occluderCentre(plate).y, 0.0f, 1e-5f);

  Scene moved = makeBuiltinScene("plate");
  placeOccludersLaterally(moved, 0.5);
  const LightFrame frame = computeLightFrame(moved.light, moved.bounds(), 90);
  const glm::vec3 offset = occluderCentre(moved) - moved.light.center;
  EXPECT_NEAR(glm::dot(offset, frame.right), 0.5f, 1e-5f);
  EXPECT_NEAR(glm::dot(offset, frame.up), 0.0f, 1e-5f);
  EXPECT_NEAR(occluderCentre(moved).y, 1.0f, 1e-5f);  // same depth along the light axis

  Scene bigger = makeBuiltinScene("plate");
  scaleLight(bigger, 2);
  EXPECT_EQ(bigger.light.width, 2.0f);
  EXPECT_EQ(bigger.objects[0].mesh.positions, makeBuiltinScene("plate").objects[0].mesh.positions);
}

TEST(Pareto, FrontierKeepsOnlyUndominatedPoints) {
  //            fast+bad  slow+good  dominated  tie-in-x-better-y  duplicate of 0
  const std::vector<double> ms = {1, 10, 5, 1, 1};
  const std::vector<double> error = {0.5, 0.1, 0.6, 0.4, 0.4};
  const auto frontier = paretoFrontier(ms, error);
  EXPECT_EQ(frontier, (std::vector<bool>{false, true, false, true, true}));
}

// The chart in three formats; the PNG has text where the x label goes.
TEST(Plot, ChartsAreWrittenAsPngSvgAndPdfWithText) {
  PlotSpec spec;
  spec.title = "t";
  spec.xLabel = "milliseconds per frame";
  spec.yLabel = "error";
  spec.seriesNames = {"a"};
  spec.points = {{2, 0.5, 0, "p", true}, {20, 0.1, 0, "q", true}, {30, 0.3, 0, "r", false}};
  const TempDirectory scratch("penumbra-bench-plot");
  const std::filesystem::path stem = scratch.path() / "plot";
  const auto paths = writePlot(stem, spec);
  ASSERT_EQ(paths.size(), 3u);
  OIIO::ImageBuf image(paths[0].string());
  ASSERT_TRUE(image.read(0, 0, true, OIIO::TypeDesc::FLOAT));
  const int h = image.spec().height;
  int dark = 0;  // the x label's band, centred under the axes
  for (int y = h - 40; y < h - 10; ++y)
    for (int x = 96; x < spec.width - 24; ++x) dark += image.getchannel(x, y, 0, 0) < 0.5f;
  EXPECT_GT(dark, 40);
  EXPECT_LT(dark, 20000);
  auto head = [](const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::string text(4096, '\0');
    file.read(text.data(), std::streamsize(text.size()));
    text.resize(size_t(file.gcount()));
    return text;
  };
  EXPECT_NE(head(paths[1]).find("<svg"), std::string::npos);
  EXPECT_EQ(head(paths[2]).rfind("%PDF", 0), 0u);
  EXPECT_THROW(writePlot("/nonexistent-directory/x", spec), std::runtime_error);
}

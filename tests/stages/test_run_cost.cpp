// Long runs of raster4d and the reference announced before they start and stoppable while
// they run (docs/decisions/061-cost-estimates-raster4d-reference.md): each stage's cost
// estimate against what the run then counts, its growth with the settings that drive it,
// the refusal over a budget with the override named and nothing written, and a reference
// cancelled between tiles reported as cancelled, never exported.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "core/run_control.h"
#include "reference/reference_cost.h"
#include "scene/scene_builtin.h"
#include "support/command.h"
#include "support/gl_test.h"
#include "support/temp_directory.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json exportCounters(const TempDirectory& dir, const std::string& name, const std::string& sets) {
  const fs::path out = dir.path() / name;
  const auto result = runPenumbra("export --width 64 --height 48 --out " + out.string() + sets);
  EXPECT_EQ(result.exitCode, 0) << result.output;
  std::ifstream in(out / "run.json");
  return in ? json::parse(in)["counters"] : json::object();
}

}  // namespace

// The reference's rays: every light sample of every covered pixel, exactly, before tracing;
// Embree is then handed at most those (a sample behind the tangent plane is not traced) and,
// on the cube's ground and faces lit from above, most of them.
TEST(ReferenceCost, EstimateBoundsTheRaysCastAndGrowsWithSamplesAndPixels) {
  const TempDirectory dir("penumbra_reference_cost");
  const std::string base = " --set reference.enabled=true --set reference.cache=false";
  double previousSteps = 0;
  for (int m : {2, 4, 8}) {
    const json c = exportCounters(dir, "m" + std::to_string(m),
                                  base + " --set reference.samples=" + std::to_string(m));
    ASSERT_TRUE(c.contains("reference.estimatedRays")) << c.dump();
    const double estimated = c["reference.estimatedRays"], cast = c["reference.raysCast"];
    std::printf("m=%d: estimated rays %.0f, cast %.0f, estimated steps %.0f\n", m, estimated,
                cast, double(c["reference.estimatedSteps"]));
    EXPECT_LE(cast, estimated) << "m=" << m;
    EXPECT_GE(cast, 0.5 * estimated) << "m=" << m;
    EXPECT_GT(double(c["reference.estimatedSteps"]), 3.9 * previousSteps) << "m=" << m;  // x m^2
    previousSteps = c["reference.estimatedSteps"];
  }
  // More pixels, more rays; more triangles (the dragon's BVH), more steps per ray.
  ReferenceRequest small, large;
  small.width = 8, small.height = 8, large.width = 16, large.height = 16;
  small.wsPosition.assign(8 * 8 * 4, 1.0f);
  large.wsPosition.assign(16 * 16 * 4, 1.0f);
  EXPECT_EQ(estimateReferenceCost(large, 12).rays, 4 * estimateReferenceCost(small, 12).rays);
  EXPECT_GT(estimateReferenceCost(small, 800000).steps, 4 * estimateReferenceCost(small, 12).steps);
}

TEST(ReferenceCost, OverTheBudgetIsRefusedWithTheOverrideAndNothingWritten) {
  const TempDirectory dir("penumbra_reference_budget");
  const fs::path out = dir.path() / "out";
  const auto result = runPenumbra("export --width 64 --height 48 --out " + out.string() +
                                  " --set reference.enabled=true --set reference.cache=false"
                                  " --set reference.budget=0.01");
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("over reference.budget=0.01 million"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("--set reference.budget="), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(out));
}

// raster4d's STEP 5 pairs from STEP 3-4's counts equal the pairs STEP 5 then tests; its
// loops grow with m (row masks: m + 1 per pair) and with the image.
TEST(Raster4dCost, EstimatedPairsEqualThePairsTestedAndGrowWithSamples) {
  const TempDirectory dir("penumbra_raster4d_cost");
  double previousLoops = 0;
  for (int m : {8, 16, 32}) {
    const json c = exportCounters(dir, "m" + std::to_string(m),
                                  " --set raster4d.enabled=true --set raster4d.samples=" +
                                      std::to_string(m));
    ASSERT_TRUE(c.contains("raster4d.estimatedPairs")) << c.dump();
    std::printf("m=%d: estimated pairs %.0f, considered %.0f, estimated loops %.0f\n", m,
                double(c["raster4d.estimatedPairs"]), double(c["raster4d.pairsConsidered"]),
                double(c["raster4d.estimatedLoops"]));
    EXPECT_GT(double(c["raster4d.pairsConsidered"]), 0.0) << "m=" << m;
    EXPECT_EQ(double(c["raster4d.estimatedPairs"]), double(c["raster4d.pairsConsidered"])) << "m=" << m;
    EXPECT_GT(double(c["raster4d.estimatedLoops"]), previousLoops) << "m=" << m;
    previousLoops = c["raster4d.estimatedLoops"];
  }
}

TEST(Raster4dCost, OverTheBudgetIsRefusedBeforeStep5) {
  PipelineRun run(makeBuiltinScene("cube"), {}, 64, 48);
  ASSERT_TRUE(run.pipeline->set("raster4d.enabled=true").empty());
  ASSERT_TRUE(run.pipeline->set("raster4d.budget=0.001").empty());
  try {
    run.run();
    ADD_FAILURE() << "the run was not refused";
  } catch (const RunBudgetExceeded& error) {
    EXPECT_EQ(error.budgetKey, "raster4d.budget");
    EXPECT_GT(error.estimate, 0.001);
    EXPECT_NE(std::string(error.what()).find("--set raster4d.budget="), std::string::npos) << error.what();
  }
  EXPECT_FALSE(run.frame->has("raster4d.visibility"));
}

// Cancelled while the reference traces (the poll hook asks once tracing is under way): the
// run throws RunCancelled naming the tiles done, and no reference or error is left to read.
TEST(ReferenceCancel, MidReferenceStopsBetweenTilesAndLeavesNoOutput) {
  PipelineRun run(makeBuiltinScene("cube"), {"reference.cache=false", "reference.samples=64"}, 128, 96);
  ASSERT_TRUE(run.pipeline->set("reference.enabled=true").empty());
  ReferenceProgress& progress = referenceStageProgress();
  setRunCancelPoll([&] {
    if (progress.running && progress.tilesDone >= 1) requestRunCancel("test");
  });
  try {
    run.run();
    ADD_FAILURE() << "the run was not cancelled";
  } catch (const RunCancelled& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("cancelled in reference after"), std::string::npos) << message;
    EXPECT_NE(message.find("of 48 tiles (test)"), std::string::npos) << message;  // 8 x 6 tiles
  }
  setRunCancelPoll(nullptr);
  clearRunCancel();
  EXPECT_LT(progress.tilesDone.load(), 48);
  EXPECT_FALSE(run.frame->has("reference.visibility"));
}

// The same through the CLI: --time-limit stops a long reference between tiles; exit 1,
// "cancelled in reference", and no export directory.
TEST(ReferenceCancel, TimeLimitStopsALongReferenceWithNothingExported) {
  const TempDirectory dir("penumbra_reference_time_limit");
  const fs::path out = dir.path() / "out";
  const auto result = runPenumbra("export --width 320 --height 240 --time-limit 3 --out " +
                                  out.string() +
                                  " --set reference.enabled=true --set reference.cache=false"
                                  " --set reference.samples=64");
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find("cancelled in reference after"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("nothing was written"), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(out));
}

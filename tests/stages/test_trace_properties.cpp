// Properties of the trace stage that need no oracle: the recorded steps add up, stepping
// never decreases, the iteration cap is never reached, a point light reproduces the hard
// shadow, and no stage writes NaN or Inf, on every built-in and stress scene.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "monte_carlo/trace/trace_steps.h"
#include "scene/scene_builtin.h"
#include "scene/scene_stress.h"
#include "support/gl_test.h"

namespace {

bool isTerminal(int decision) {
  return decision == STEP_HIT || decision == STEP_MISS || decision == STEP_EARLY_BACKFACE ||
         decision == STEP_EARLY_INSIDE || decision == STEP_EARLY_REGION;
}

// A pixel (image coordinates, row 0 on top) whose unfiltered visibility is strictly
// between 0 and 1: a penumbra pixel.
bool findPenumbraPixel(const PipelineRun& run, int& x, int& y) {
  const auto visibility = run.read("trace.visibility");
  const int w = run.frame->eyeWidth, h = run.frame->eyeHeight;
  for (int row = h / 2; row < h; ++row)
    for (int column = 0; column < w; ++column) {
      const float v = visibility[size_t(row) * w + column];
      if (v > 0.2f && v < 0.8f) {
        x = column;
        y = h - 1 - row;
        return true;
      }
    }
  return false;
}

Scene loadSceneForTest(const std::string& name) {
  std::vector<std::string> warnings;
  return loadScene(name, warnings);
}

}  // namespace

class TraceRecords : public ::testing::TestWithParam<const char*> {};

TEST_P(TraceRecords, DecisionsAddUpToTheVisibilityAndSteppingNeverDecreases) {
  const std::string search = GetParam();
  const std::vector<std::string> sets = {"trace.search=" + search, "trace.rays=3",
                                         "trace.use_classification=false",
                                         "light.resolution=256"};
  PipelineRun first(makeBuiltinScene("cube"), sets, 160, 160);
  int x = -1, y = -1;
  ASSERT_TRUE(findPenumbraPixel(first, x, y));
  auto recordSets = sets;
  recordSets.push_back("trace.record_x=" + std::to_string(x));
  recordSets.push_back("trace.record_y=" + std::to_string(y));
  PipelineRun run(makeBuiltinScene("cube"), recordSets, 160, 160);
  const auto visibility = run.read("trace.visibility");
  const float pixelVisibility = visibility[size_t(159 - y) * 160 + x];
  EXPECT_EQ(pixelVisibility, first.read("trace.visibility")[size_t(159 - y) * 160 + x]);

  std::map<int, std::vector<gpu::TraceStep>> byRay;
  for (const gpu::TraceStep& step : recordedTraceSteps(*run.frame)) byRay[step.header.x].push_back(step);
  ASSERT_EQ(byRay.size(), 9u) << "every one of the 3 x 3 rays leaves a record";
  int unblocked = 0;
  for (const auto& [ray, steps] : byRay) {
    int terminals = 0;
    for (const auto& step : steps) terminals += isTerminal(step.header.z);
    EXPECT_EQ(terminals, 1) << "ray " << ray << " has exactly one terminal decision";
    const int last = steps.back().header.z;
    EXPECT_TRUE(isTerminal(last)) << "ray " << ray << " ends with a terminal decision";
    unblocked += last == STEP_MISS || last == STEP_EARLY_REGION;
    if (search != "hierarchical") continue;  // bisection steps go back and forth by design
    for (size_t i = 0; i < steps.size(); ++i) {
      EXPECT_GE(steps[i].stepping.y, steps[i].stepping.x) << "ray " << ray << " step " << i;
      if (i > 0) {
        EXPECT_GE(steps[i].stepping.x, steps[i - 1].stepping.y - 1e-6f) << "ray " << ray;
      }
    }
  }
  EXPECT_FLOAT_EQ(pixelVisibility, unblocked / 9.0f);
}

INSTANTIATE_TEST_SUITE_P(Searches, TraceRecords,
                         ::testing::Values("hierarchical", "linear_binary", "linear"));

// The deferred pass compiles the step records out and traces the recorded pixel again with
// them; the forward pass switches to the recording variant (shaders/shared/trace_ray.glsl):
// recording a pixel must change no value and no count, in each way the trace runs, over
// both hierarchies and with a second search.
TEST(TraceRecording, RecordingAPixelChangesNoOutputAndNoCount) {
  const std::vector<std::vector<std::string>> ways = {
      {"trace.deferred=true", "trace.use_classification=true", "trace.hierarchy=minmax"},
      {"trace.deferred=true", "trace.use_classification=true", "trace.hierarchy=nbuffer"},
      {"trace.deferred=true", "trace.use_classification=false", "trace.hierarchy=nbuffer"},
      {"trace.deferred=true", "trace.use_classification=true", "trace.search=linear_binary"},
      {"trace.deferred=false", "trace.hierarchy=nbuffer"}};
  for (const auto& way : ways) {
    std::vector<std::string> sets = {"trace.rays=2", "light.resolution=256"};
    sets.insert(sets.end(), way.begin(), way.end());
    std::string where;
    for (const std::string& set : way) where += set + " ";
    PipelineRun plain(makeBuiltinScene("cube"), sets, 120, 120);
    int x = -1, y = -1;
    ASSERT_TRUE(findPenumbraPixel(plain, x, y)) << where;
    sets.push_back("trace.record_x=" + std::to_string(x));
    sets.push_back("trace.record_y=" + std::to_string(y));
    PipelineRun recorded(makeBuiltinScene("cube"), sets, 120, 120);
    EXPECT_GT(recordedTraceSteps(*recorded.frame).size(), 4u) << where;
    EXPECT_TRUE(recordedTraceSteps(*plain.frame).empty()) << where;
    EXPECT_EQ(recorded.read("trace.visibility"), plain.read("trace.visibility")) << where;
    EXPECT_EQ(recorded.read("trace.cost"), plain.read("trace.cost")) << where;
    for (const char* counter : {"trace.rays", "trace.raysSearched", "trace.fetches",
                                "trace.iterations", "trace.earlyOutRegion"})
      EXPECT_EQ(recorded.frame->counters.at(counter), plain.frame->counters.at(counter))
          << counter << ", " << where;
  }
}

// record_x / record_y may name a pixel off the image (the parameters' ranges do not know
// the eye size): the recording pass then reads nothing and records nothing.
TEST(TraceRecording, APixelOffTheImageRecordsNothing) {
  for (const char* classification : {"true", "false"}) {
    const std::vector<std::string> sets = {"trace.rays=2", "light.resolution=256",
                                           std::string("trace.use_classification=") + classification};
    PipelineRun plain(makeBuiltinScene("cube"), sets, 120, 120);
    auto offImage = sets;
    offImage.push_back("trace.record_x=500");
    offImage.push_back("trace.record_y=20");
    PipelineRun recorded(makeBuiltinScene("cube"), offImage, 120, 120);
    EXPECT_TRUE(recordedTraceSteps(*recorded.frame).empty()) << classification;
    EXPECT_EQ(recorded.read("trace.visibility"), plain.read("trace.visibility")) << classification;
    EXPECT_EQ(recorded.frame->counters.at("trace.rays"), plain.frame->counters.at("trace.rays"))
        << classification;
  }
}

TEST(TraceStability, EveryOutputFiniteAndVisibilityInRangeOnEveryScene) {
  std::vector<std::string> scenes = {"cube", "plate", "spheres", "engine"};
  for (const std::string& stress : stressSceneNames()) scenes.push_back(stress);
  for (const std::string& name : scenes)
    for (const char* search : {"hierarchical", "linear_binary"})
      for (const char* layers : {"two", "three"}) {
        PipelineRun run(loadSceneForTest(name),
                        {std::string("trace.search=") + search, std::string("light.layers=") + layers,
                         "light.resolution=128"},
                        96, 96);
        const std::string where = name + " " + search + " " + layers;
        for (const auto& [key, texture] : run.frame->textures)
          for (int layer = 0; layer < std::max(texture.layers(), 1); ++layer)
            for (float value : texture.readFloats(layer))
              ASSERT_TRUE(std::isfinite(value)) << key << " on " << where;
        for (const char* key : {"trace.visibility", "filter.visibility", "hard_shadow.visibility"})
          for (float value : run.read(key)) {
            ASSERT_GE(value, 0.0f) << key << " on " << where;
            ASSERT_LE(value, 1.0f) << key << " on " << where;
          }
        EXPECT_EQ(run.frame->counters.at("trace.iterationCapReached"), 0) << where;
      }
}

TEST(TraceStability, IterationCapNeverReachedOnTheEngine) {
  for (const char* search : {"hierarchical", "linear_binary"}) {
    PipelineRun run(makeBuiltinScene("engine"),
                    {std::string("trace.search=") + search, "trace.rays=2"}, 128, 128);
    EXPECT_EQ(run.frame->counters.at("trace.iterationCapReached"), 0) << search;
    EXPECT_GT(run.frame->counters.at("trace.raysSearched"), 100) << search;
  }
}

// A light of (almost) zero size: every ray goes to the same point, so the trace is the
// hard shadow (up to the different bias: along the ray vs along the light axis).
TEST(TraceVersusHardShadow, PointLightGivesTheHardShadow) {
  for (const char* name : {"plate", "cube"}) {
    Scene scene = makeBuiltinScene(name);
    scene.light.width = scene.light.height = 1e-3f;
    PipelineRun run(scene, {"trace.rays=2", "light.resolution=512"}, 200, 200);
    const auto traced = run.read("trace.visibility");
    const auto hard = run.read("hard_shadow.visibility");
    int differ = 0, shadowed = 0;
    for (size_t i = 0; i < traced.size(); ++i) {
      differ += (traced[i] >= 0.5f) != (hard[i] >= 0.5f);
      shadowed += hard[i] < 0.5f;
    }
    EXPECT_GT(shadowed, 500) << name;
    // Differences only where the biases disagree: a thin rim along shadow borders.
    EXPECT_LT(differ, int(0.01 * traced.size())) << name << ": " << differ << " pixels differ";
  }
}

// Demand: a run that asks only for the composite writes no cost image (the deferred pass is
// compiled without its store) and changes no result: the same composite, visibility and
// counters to the last bit, with and without a recorded pixel; asked for, the cost is there.
TEST(TraceDemand, CostNotAskedForIsNotWrittenAndChangesNoResult) {
  auto traceCounters = [](const Frame& frame) {
    std::map<std::string, double> trace;
    for (const auto& [name, value] : frame.counters)
      if (name.rfind("trace.", 0) == 0) trace[name] = value;
    return trace;
  };
  for (const std::string record : {"trace.record_x=-1", "trace.record_x=40"}) {
    PipelineRun run(makeBuiltinScene("cube"),
                    {"light.resolution=128", "trace.rays=2", "trace.search=hierarchical", record,
                     "trace.record_y=30"},
                    96, 72);
    const auto composite = run.read("composite.color");
    const auto visibility = run.read("trace.visibility");
    const auto counters = traceCounters(*run.frame);
    ASSERT_GT(counters.at("trace.fetches"), 0.0);
    const size_t steps = recordedTraceSteps(*run.frame).size();
    ASSERT_TRUE(run.frame->has("trace.cost"));
    run.pipeline->run(*run.frame, {"composite.color"});
    EXPECT_FALSE(run.frame->has("trace.cost")) << record;
    EXPECT_EQ(run.read("composite.color"), composite) << record;
    EXPECT_EQ(run.read("trace.visibility"), visibility) << record;
    EXPECT_EQ(traceCounters(*run.frame), counters) << record;
    EXPECT_EQ(recordedTraceSteps(*run.frame).size(), steps) << record;
    run.pipeline->run(*run.frame, {"trace.cost"});
    EXPECT_TRUE(run.frame->has("trace.cost")) << record;
  }
}

// The totals (trace.rays, .raysSearched, .fetches, .iterations, the early outs) are added up
// from per-pixel records by a pass of their own (trace_totals.comp); the cost image holds the
// same counts per pixel, written by the trace pass from its own registers. Its sums must equal
// the totals, with the listed pixels and with every pixel (an eye of 203 x 150 pixels: no
// multiple of the reduction's 64 records per invocation or 64 invocations per group), and
// the rays must be n^2 per pixel that traced: penumbra with classification, every receiver
// in the light's frustum without.
TEST(TraceTotals, EqualTheCostImageSummedAndTheRaysPerTracedPixel) {
  for (const char* classification : {"true", "false"})
    for (const char* scene : {"cube", "spheres"}) {
      const std::string where = std::string(scene) + ", classification " + classification;
      PipelineRun run(makeBuiltinScene(scene),
                      {"trace.rays=3", "light.resolution=256", "trace.deferred=true",
                       std::string("trace.use_classification=") + classification},
                      203, 150);
      const auto cost = run.read("trace.cost");
      double fetches = 0, iterations = 0, searched = 0, earlyOuts = 0;
      for (size_t i = 0; i < cost.size(); i += 4)
        fetches += cost[i], iterations += cost[i + 1], searched += cost[i + 2],
            earlyOuts += cost[i + 3];
      const auto& c = run.frame->counters;
      EXPECT_EQ(c.at("trace.fetches"), fetches) << where;
      EXPECT_EQ(c.at("trace.iterations"), iterations) << where;
      EXPECT_EQ(c.at("trace.raysSearched"), searched) << where;
      EXPECT_EQ(c.at("trace.earlyOutBackface") + c.at("trace.earlyOutInside") +
                    c.at("trace.earlyOutRegion"),
                earlyOuts)
          << where;
      EXPECT_GT(searched, 0.0) << where;
      const double traced = std::string(classification) == "true"
                                ? c.at("classify.penumbra")
                                : c.at("classify.lit") + c.at("classify.penumbra") +
                                      c.at("classify.umbra");
      EXPECT_EQ(c.at("trace.rays"), 9 * traced) << where;
    }
}

// The temporal-stability measure (app/stats/temporal.h, docs/decisions/120-temporal-stability.md):
// against small arrays computed by hand, then through the pipeline: exactly 0 for every
// method on a static scene with a fixed frame key (nothing a stage computes depends on
// anything but the scene and the key), positive for Monte Carlo when the key changes per
// frame (its light samples are the hash of pixel, ray and key: decision 010).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "reference/error_metrics.h"
#include "scene/scene_builtin.h"
#include "stats/temporal.h"
#include "support/gl_test.h"

namespace {

// Five pixels: 0 the method changed where the truth did not; 1 and 3 nothing changed; 2 the
// truth changed (a moving shadow edge: not a stable pixel); 4 does not count.
const std::vector<float> kMethod0 = {0.0f, 0.5f, 1.0f, 0.25f, 0.75f};
const std::vector<float> kMethod1 = {0.5f, 0.5f, 0.0f, 0.25f, 0.5f};
const std::vector<float> kReference0 = {0.0f, 0.5f, 1.0f, 0.5f, 1.0f};
const std::vector<float> kReference1 = {0.0f, 0.5f, 0.0f, 0.5f, 1.0f};
const std::vector<std::uint8_t> kCounted = {1, 1, 1, 1, 0};

}  // namespace

TEST(Temporal, HandComputedFivePixels) {
  const TemporalChange c = temporalChange(kMethod0, kMethod1, kReference0, kReference1, kCounted);
  EXPECT_EQ(c.counted, 4u);
  EXPECT_EQ(c.stable, 3u);
  EXPECT_DOUBLE_EQ(c.change, 0.5 / 3);           // (0.5 + 0 + 0) / 3
  EXPECT_DOUBLE_EQ(c.maxChange, 0.5);
  EXPECT_DOUBLE_EQ(c.referenceChange, 0.25);     // (0 + 0 + 1 + 0) / 4
  EXPECT_DOUBLE_EQ(c.methodChange, 0.375);       // (0.5 + 0 + 1 + 0) / 4
  ASSERT_TRUE(c.hasRatio());
  EXPECT_DOUBLE_EQ(c.ratio(), (0.5 / 3) / 0.25);
  // A tolerance of 1 takes pixel 2 as stable: its change 1 counts.
  const TemporalChange loose = temporalChange(kMethod0, kMethod1, kReference0, kReference1, kCounted, 1.0f);
  EXPECT_EQ(loose.stable, 4u);
  EXPECT_DOUBLE_EQ(loose.change, 1.5 / 4);
  EXPECT_DOUBLE_EQ(loose.maxChange, 1.0);
}

TEST(Temporal, StaticTruthHasNoRatio) {
  // The reference the same in both frames: every counted pixel is stable, the ratio undefined.
  const TemporalChange c = temporalChange(kMethod0, kMethod1, kReference0, kReference0, kCounted);
  EXPECT_EQ(c.stable, 4u);
  EXPECT_DOUBLE_EQ(c.change, 1.5 / 4);
  EXPECT_EQ(c.referenceChange, 0.0);
  EXPECT_FALSE(c.hasRatio());
  EXPECT_EQ(c.ratio(), 0.0);
  // The method the same in both frames: exactly 0.
  const TemporalChange still = temporalChange(kMethod1, kMethod1, kReference0, kReference0, kCounted);
  EXPECT_EQ(still.change, 0.0);
  EXPECT_EQ(still.maxChange, 0.0);
  EXPECT_TRUE(still.defined());
}

TEST(Temporal, NothingCountedIsUndefinedAndNonFiniteSkipped) {
  const TemporalChange none =
      temporalChange(kMethod0, kMethod1, kReference0, kReference1, std::vector<std::uint8_t>(5, 0));
  EXPECT_FALSE(none.defined());
  EXPECT_FALSE(none.hasRatio());
  EXPECT_EQ(none.change, 0.0);
  std::vector<float> method1 = kMethod1;
  method1[0] = std::numeric_limits<float>::quiet_NaN();  // pixel 0 drops out
  const TemporalChange c = temporalChange(kMethod0, method1, kReference0, kReference1, kCounted);
  EXPECT_EQ(c.counted, 3u);
  EXPECT_EQ(c.stable, 2u);
  EXPECT_EQ(c.change, 0.0);
  EXPECT_DOUBLE_EQ(c.referenceChange, 1.0 / 3);
  EXPECT_TRUE(std::isfinite(c.ratio()));
}

TEST(Temporal, SizesMustAgree) {
  EXPECT_THROW(temporalChange(kMethod0, {0.f}, kReference0, kReference1, kCounted), std::invalid_argument);
  EXPECT_THROW(bothCounted({1, 0}, {1, 1, 1}, 3), std::invalid_argument);
  EXPECT_EQ(bothCounted({1, 0, 1}, {1, 1, 0}, 3), (std::vector<std::uint8_t>{1, 0, 0}));
  EXPECT_EQ(bothCounted({}, {}, 2), (std::vector<std::uint8_t>{1, 1}));
}

TEST(Temporal, SummaryOverPairs) {
  TemporalChange a, b, undefined;
  a.change = 0.5 / 3, a.referenceChange = 0.25, a.stable = 3, a.methodChange = 0.375, a.maxChange = 0.5;
  b.change = 0.5, b.referenceChange = 0, b.stable = 4, b.methodChange = 0.5, b.maxChange = 0.75;
  undefined.maxChange = 1;  // no stable pixel: not counted
  const TemporalSummary s = summarizeTemporal({a, b, undefined});
  EXPECT_EQ(s.pairs, 2);
  EXPECT_DOUBLE_EQ(s.meanChange, (0.5 / 3 + 0.5) / 2);
  EXPECT_DOUBLE_EQ(s.worstChange, 0.5);
  EXPECT_DOUBLE_EQ(s.worstPixel, 0.75);
  EXPECT_DOUBLE_EQ(s.meanReferenceChange, 0.125);
  ASSERT_TRUE(s.hasRatio());
  EXPECT_DOUBLE_EQ(s.ratio(), ((0.5 / 3 + 0.5) / 2) / 0.125);
  EXPECT_FALSE(summarizeTemporal({b}).hasRatio());  // a static truth: no ratio
  EXPECT_FALSE(summarizeTemporal({}).hasRatio());
}

namespace {

// Every method's visibility, the reference and the counted pixels of one frame of `run`
// at frame key `key`, in a new Frame (as the window makes one for each pose).
struct FrameArrays {
  std::map<std::string, std::vector<float>> methods;
  std::vector<float> reference;
  std::vector<std::uint8_t> counted;
};

FrameArrays runFrame(PipelineRun& run, std::uint32_t key) {
  const int width = run.frame->eyeWidth, height = run.frame->eyeHeight;
  run.frame = std::make_unique<Frame>(run.scene, *run.gpuScene, *run.pipeline);
  run.frame->eyeWidth = width, run.frame->eyeHeight = height;
  run.frame->frameKey = key;
  run.run();
  FrameArrays arrays;
  for (const std::string& method : run.pipeline->methods())
    if (method != "reference") arrays.methods[method] = run.read(run.pipeline->methodOutput(method));
  arrays.reference = run.read("reference.visibility");
  arrays.counted = countedPixels(run.read("classify.mask"));
  return arrays;
}

}  // namespace

TEST(Temporal, ZeroForEveryMethodWithAFixedKeyPositiveForMonteCarloPerFrameKey) {
  PipelineRun run(makeBuiltinScene("cube"),
                  {"raster4d.enabled=true", "raster4d.samples=8", "reference.enabled=true",
                   "reference.cache=false", "reference.samples=4"},
                  64, 48);
  const FrameArrays first = runFrame(run, 0), again = runFrame(run, 0), nextKey = runFrame(run, 1);
  const std::vector<std::uint8_t> counted = bothCounted(first.counted, again.counted, first.reference.size());
  ASSERT_EQ(first.reference, again.reference) << "the reference is deterministic";
  for (const auto& [method, visibility] : first.methods) {
    const TemporalChange c = temporalChange(visibility, again.methods.at(method), first.reference,
                                            again.reference, counted);
    EXPECT_GT(c.stable, 1000u) << method;
    EXPECT_EQ(c.stable, c.counted) << method << ": the truth holds still everywhere";
    EXPECT_EQ(c.change, 0.0) << method << " changed with the same key on a static scene";
    EXPECT_FALSE(c.hasRatio()) << method;
  }
  // The Monte Carlo trace and its filtered result swim when the key changes; so much that
  // the mean over the counted pixels (most of them lit or umbra, unchanged) is measurable.
  for (const char* method : {"trace", "filter"}) {
    ASSERT_TRUE(first.methods.count(method)) << method;
    const TemporalChange c = temporalChange(first.methods.at(method), nextKey.methods.at(method),
                                            first.reference, nextKey.reference, counted);
    EXPECT_GT(c.change, 1e-4) << method << " did not change with a new frame key";
    EXPECT_GT(c.maxChange, 0.1) << method;
  }
}

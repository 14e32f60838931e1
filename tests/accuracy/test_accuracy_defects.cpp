// The five defects of issue 12, each measured against the analytic oracle
// (tests/support/analytic_visibility.h) on a scene of the accuracy suite. Each test failed
// before its fix; the numbers before/after are in docs/accuracy.md.
#include <gtest/gtest.h>

#include <cstdio>

#include "support/analytic_scenes.h"
#include "support/gl_test.h"

namespace {

AnalyticError measure(const std::string& scene, const std::vector<std::string>& sets,
                      const std::string& output, int width = 256, int height = 192) {
  PipelineRun run(makeAnalyticScene(scene), sets, width, height);
  const AnalyticError e = compareWithAnalytic(run.read(output), analyticImage(run));
  std::printf("%s %s: mean |error| in shadow %.4f, signed %+.4f, max %.3f, umbra mean %.4f "
              "(%zu pixels in shadow)\n",
              scene.c_str(), output.c_str(), e.meanAbsInShadow, e.meanSigned, e.maxAbs,
              e.meanInUmbra, e.pixelsInShadow);
  return e;
}

// 1. The reference's ray-origin offset no longer grows with a receiver-only ground: a plate
//    0.06 above a 1000-unit ground (before: mean |error| in shadow 0.066, all too bright).
TEST(AccuracyDefects, ReferenceKeepsContactShadowsOnAHugeGround) {
  const AnalyticError e = measure(
      "huge_ground", {"reference.enabled=true", "reference.cache=false"}, "reference.visibility");
  EXPECT_GT(e.pixelsInShadow, 100u);
  EXPECT_LE(e.meanAbsInShadow, 0.01);
  EXPECT_LE(e.meanSigned, 0.003);
}

}  // namespace

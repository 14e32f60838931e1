// The five defects of issue 12, each measured against the analytic oracle
// (tests/support/analytic_visibility.h) on a scene of the accuracy suite. Each test failed
// before its fix; the numbers before/after are in docs/accuracy.md.
#include <gtest/gtest.h>

#include <cstdio>

#include "support/analytic_scenes.h"
#include "scene/eye_frustum.h"
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

namespace {

// 2. The eye's near/far come from what the camera sees (app/scene/eye_frustum.h): a 5000-unit
//    ground and a camera 1.3 units from the plate (before: the near plane was 7 units out
//    and nothing was drawn).
TEST(AccuracyDefects, HugeGroundDoesNotEmptyTheImage) {
  Scene scene = makeAnalyticScene("huge_ground");
  for (glm::vec3& p : scene.objects[0].mesh.positions) p *= 5.0f;  // 1000 -> 5000 units
  scene.camera = {{0, 0.9f, 1.0f}, {0, 0, 0}, {0, 1, 0}, 45};
  PipelineRun run(std::move(scene), {}, 128, 96);
  const std::vector<float> positions = run.read("gbuffer.wsPosition");
  size_t covered = 0;
  for (size_t i = 3; i < positions.size(); i += 4) covered += positions[i] != 0;
  EXPECT_EQ(covered, positions.size() / 4) << "every pixel sees the ground or the plate";
  const AnalyticError e = compareWithAnalytic(run.read("trace.visibility"), analyticImage(run));
  EXPECT_GT(e.pixelsInShadow, 500u);
  EXPECT_EQ(e.outOfRange, 0u);
}

TEST(AccuracyDefects, EyeDepthRangeFollowsWhatTheCameraSees) {
  Scene scene = makeAnalyticScene("huge_ground");
  for (glm::vec3& p : scene.objects[0].mesh.positions) p *= 5.0f;
  scene.camera = {{0, 0.9f, 1.0f}, {0, 0, 0}, {0, 1, 0}, 45};
  const EyeDepthRange close = eyeDepthRange(scene, 4.0f / 3.0f);
  EXPECT_TRUE(close.seesGeometry);
  // The view's lower edge meets the ground 0.92 units along the axis, its upper edge 2.5
  // (19.5 degrees below the horizon, 0.9 units up): near/far hug that, not the ground's size.
  EXPECT_GT(close.eyeNear, 0.6f);
  EXPECT_LT(close.eyeNear, 0.92f);
  EXPECT_GT(close.eyeFar, 2.4f);
  EXPECT_LT(close.eyeFar, 3.0f);
  scene.camera = {{0, 0.9f, 1.0f}, {0, 5, 1.0f}, {0, 0, 1}, 45};  // looking straight up
  EXPECT_FALSE(eyeDepthRange(scene, 4.0f / 3.0f).seesGeometry);
}

}  // namespace

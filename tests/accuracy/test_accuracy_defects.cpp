// The five defects of docs/accuracy.md, each measured against the analytic oracle
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

namespace {

// 3. The filter respects geometry (plane distance, normals, penumbra width): on the contact
//    cases it no longer blurs the lit plate top and the lit ground into the dark strip under
//    the plate's edge (before: filtered 0.354 against 0.065 unfiltered), and it still
//    removes most of the noise where the penumbra is wide. At the fixed 512^2 map and 2x2
//    rays where the defect was measured, and at the defaults (auto: 2048^2 and 5x5 on the
//    contact plates, a penumbra narrower than a pixel, where a Gaussian of 0.4 pixels still
//    doubled the error until the kernel was cut at 2 sigma).
TEST(AccuracyDefects, FilterDoesNotBleedAcrossContactEdges) {
  for (const std::string scene : {"plate_contact", "huge_ground", "plate_mid", "box"}) {
    PipelineRun run(makeAnalyticScene(scene), {"light.resolution=512", "trace.rays=2"}, 256, 192);
    const std::vector<double> exact = analyticImage(run);
    const AnalyticError traced = compareWithAnalytic(run.read("trace.visibility"), exact);
    const AnalyticError filtered = compareWithAnalytic(run.read("filter.visibility"), exact);
    std::printf("%s: unfiltered %.4f, filtered %.4f\n", scene.c_str(), traced.meanAbsInShadow,
                filtered.meanAbsInShadow);
    EXPECT_LE(filtered.meanAbsInShadow, 1.1 * traced.meanAbsInShadow) << scene;
    if (scene == "plate_mid") {
      EXPECT_LE(filtered.meanAbsInShadow, 0.3 * traced.meanAbsInShadow) << scene;
    }
  }
  PipelineRun contact(makeAnalyticScene("plate_contact"), {}, 256, 192);
  const std::vector<double> exact = analyticImage(contact);
  const AnalyticError traced = compareWithAnalytic(contact.read("trace.visibility"), exact);
  const AnalyticError filtered = compareWithAnalytic(contact.read("filter.visibility"), exact);
  std::printf("plate_contact at the defaults: unfiltered %.4f, filtered %.4f\n",
              traced.meanAbsInShadow, filtered.meanAbsInShadow);
  EXPECT_LE(filtered.meanAbsInShadow, 1.1 * traced.meanAbsInShadow);
}

// 7. The normal offset (light.normal_offset, docs/accuracy.md fix 7) is capped by the
//    contact distance (bias.glsl). At a fixed 128^2 map one texel at the contact plate is
//    0.054 wide, almost its 0.06 gap: the full one-texel offset plus the Eq 3.2 bias (0.7
//    texel) lifted every ray's end above the plate and the shadow under it was lost (before:
//    trace 8x8, umbra mean +1.0, mean |error| in shadow 0.638). The bound from the texel
//    size: a depth map puts the plate's outline within half a texel of the true one, so a
//    ground point in the exact umbra more than half a texel inside its edge is in the umbra
//    of the rasterized plate too, and must be dark. Over the whole shadow a coarse bound: at
//    most twice the error with no offset at all (the depth map's own limit at this texel
//    size; uncapped it was 6.8x, capped 1.13x: pixels at the plate's sides whose texel the
//    rasterized plate does not cover, where the hard shadow is as wrong).
TEST(AccuracyDefects, NormalOffsetKeepsContactShadowsAtCoarseMaps) {
  const std::vector<std::string> sets = {"light.resolution=128", "trace.rays=8"};
  PipelineRun run(makeAnalyticScene("plate_contact"), sets, 256, 192);
  const std::vector<double> exact = analyticImage(run);
  const std::vector<float> traced = run.read("trace.visibility");
  const std::vector<float> positions = run.read("gbuffer.wsPosition");
  const LightFrame& light = run.frame->light;
  const glm::vec3 plateCentre(0, 0.06f, 0);
  const float texel = 2.0f * glm::dot(plateCentre - light.wsProjectionPoint, light.forward) *
                      std::max(light.tanHalfFovX, light.tanHalfFovY) / 128.0f;
  // The exact umbra starts half the contact penumbra (PCSS: 1 x 0.06 / 2.94 = 0.0204) inside
  // the outline; the rasterized plate's umbra at most half a texel farther in.
  const float deep = 0.5f * 0.0204f + 0.5f * texel;
  size_t deepPixels = 0;
  double deepSum = 0;
  for (size_t i = 0; i < exact.size(); ++i) {
    const float x = positions[4 * i], y = positions[4 * i + 1], z = positions[4 * i + 2];
    const float inside = 0.5f - std::max(std::fabs(x), std::fabs(z));  // from the outline
    if (exact[i] < 0 || exact[i] >= 0.1 || std::fabs(y) > 1e-3f || inside <= deep) continue;
    ++deepPixels;
    deepSum += traced[i];
  }
  std::printf("plate_contact 128^2: texel %.4f, %zu umbra pixels more than %.4f inside the "
              "outline, mean traced visibility %.4f\n",
              texel, deepPixels, deep, deepPixels ? deepSum / double(deepPixels) : 0.0);
  EXPECT_NEAR(texel, 0.054, 0.003);
  EXPECT_GT(deepPixels, 10u);
  EXPECT_LE(deepSum / double(std::max<size_t>(deepPixels, 1)), 0.05);
  const AnalyticError capped = compareWithAnalytic(traced, exact);
  std::vector<std::string> noOffset = sets;
  noOffset.push_back("light.normal_offset=0");
  const AnalyticError none = measure("plate_contact", noOffset, "trace.visibility");
  std::printf("plate_contact 128^2 trace: mean |error| in shadow %.4f (offset capped), %.4f "
              "(no offset)\n", capped.meanAbsInShadow, none.meanAbsInShadow);
  EXPECT_LE(capped.meanAbsInShadow, 2.0 * none.meanAbsInShadow);
}

// 4. A tilted zero-thickness sheet does not leak (light_layers.close_risers): at 8x8 rays
//    and a 2048^2 map, the mean visibility error where the exact visibility is below 0.1
//    (before: +0.0105; measured with close_risers off to show the test sees the leak).
TEST(AccuracyDefects, TiltedSheetDoesNotLeak) {
  const std::vector<std::string> sets = {"light.resolution=2048", "trace.rays=8"};
  const AnalyticError fixed = measure("tilted_plate", sets, "trace.visibility", 128, 96);
  EXPECT_GT(fixed.pixelsInUmbra, 200u);
  EXPECT_LE(fixed.meanInUmbra, 0.003);
  std::vector<std::string> open = sets;
  open.push_back("light_layers.close_risers=false");
  EXPECT_GT(measure("tilted_plate", open, "trace.visibility", 128, 96).meanInUmbra, 0.006);
}

}  // namespace

namespace {

// 5. Three layers (§3.4) no longer leak at silhouettes (the eye-layer test looks at the 3x3
//    pixels around a point's projection) nor between stacked occluders (both ends of a
//    texel's part of the ray are tested). Before: tiny light, three layers mean |error| in
//    shadow 0.029 against 0.0087 with two, max 0.60; stacked plates +0.070 in the umbra.
TEST(AccuracyDefects, ThreeLayersDoNotLeakAtSilhouettes) {
  const auto two = [](const std::string& scene) {
    return measure(scene, {"light.layers=two", "trace.rays=4"}, "trace.visibility");
  };
  const auto three = [](const std::string& scene) {
    return measure(scene, {"light.layers=three", "trace.rays=4"}, "trace.visibility");
  };
  const AnalyticError tinyTwo = two("tiny_light"), tinyThree = three("tiny_light");
  EXPECT_LE(tinyThree.meanAbsInShadow, 1.2 * tinyTwo.meanAbsInShadow);
  EXPECT_LE(tinyThree.maxAbs, tinyTwo.maxAbs + 0.05);
  EXPECT_LE(three("plate_mid").meanAbsInShadow, 1.2 * two("plate_mid").meanAbsInShadow);
  const AnalyticError stacked = three("stacked_plates");
  EXPECT_GT(stacked.pixelsInUmbra, 500u);
  EXPECT_LE(stacked.meanInUmbra, 0.005);
}

// 5b. Nor under an outline seen at a grazing angle: at 128x96 the plate's top
//     changes its distance from the eye by more than trace.eye_tolerance across one pixel, so
//     a ray crossing the plate near its front edge was "in front of" the pixel centre's
//     sample, with no neighbour showing the plate nearer the eye, and leaked; the eye-layer
//     test now compares with each pixel's tangent plane. Before (built-in plate, 128x96,
//     defaults): three layers 0.0893 against two layers 0.0799 mean |error| in shadow, 146
//     pixels differing by more than 0.2.
TEST(AccuracyDefects, ThreeLayersDoNotLeakUnderAnOutlineSeenAtAGrazingAngle) {
  const AnalyticError two = measure("plate_mid", {"light.layers=two"}, "trace.visibility", 128, 96);
  const AnalyticError three = measure("plate_mid", {"light.layers=three"}, "trace.visibility", 128, 96);
  EXPECT_GT(two.pixelsInShadow, 100u);
  EXPECT_LE(three.meanAbsInShadow, two.meanAbsInShadow + 0.002);
  EXPECT_LE(three.meanSigned, two.meanSigned + 0.002) << "three layers brighter";
}

}  // namespace

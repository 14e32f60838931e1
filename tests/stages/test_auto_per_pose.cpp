// `auto` on an animated scene (stages/shared_inputs/light/auto_settings.h,
// docs/decisions/140-auto-per-pose.md): its choice at a pose depends on that pose alone. After
// the poses before it, the settings at time t equal, field for field, those of the static
// scene at t analysed from scratch; and a pose costs one Embree build and about one ray per
// probe point.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "scene/animation.h"
#include "scene/light_frame.h"
#include "scene/scene_builtin.h"
#include "shared_inputs/light/auto_frustum.h"
#include "shared_inputs/light/auto_settings.h"

namespace {

// The light stage's inputs for a scene: its light frame with the auto field of view.
AutoSettings settingsFor(const Scene& scene, int width, int height) {
  const FrustumFit fit = fitLightFrustum(scene, 150);
  const LightFrame light = computeLightFrame(scene.light, scene.bounds(), float(fit.fovDegrees));
  return chooseAutoSettings(scene, light, width, height);
}

// The scene posed at t as a static scene: no animation left, as if loaded from a file.
Scene staticAt(const Scene& animated, double t) {
  Scene posed = poseAt(animated, t);
  posed.animation = Animation{};
  posed.time = 0;
  return posed;
}

void expectSame(const AutoSettings& want, const AutoSettings& got, const std::string& what) {
  EXPECT_EQ(want.resolution, got.resolution) << what;
  EXPECT_EQ(want.layers, got.layers) << what;
  EXPECT_EQ(want.raysPerSide, got.raysPerSide) << what;
  EXPECT_EQ(want.probes, got.probes) << what;
  EXPECT_EQ(want.neededResolution, got.neededResolution) << what;
  EXPECT_EQ(want.affordableResolution, got.affordableResolution) << what;
  EXPECT_EQ(want.halfAreaResolution, got.halfAreaResolution) << what;
  EXPECT_EQ(want.smallestPenumbraWorld, got.smallestPenumbraWorld) << what;  // bit for bit
  EXPECT_EQ(want.smallestPenumbraTexels, got.smallestPenumbraTexels) << what;
  EXPECT_EQ(want.smallestPenumbraPixels, got.smallestPenumbraPixels) << what;
  EXPECT_EQ(want.depthComplexity, got.depthComplexity) << what;
  EXPECT_EQ(want.separateOccluderProbes, got.separateOccluderProbes) << what;
  EXPECT_EQ(want.reasons, got.reasons) << what;
  EXPECT_EQ(want.ssmNeed.resolution, got.ssmNeed.resolution) << what;
  EXPECT_EQ(want.ssmNeed.exact, got.ssmNeed.exact) << what;
}

// Objects whose positions differ between two poses (counted here, not by auto).
int movedObjects(const Scene& a, const Scene& b) {
  int moved = 0;
  for (size_t i = 0; i < a.objects.size(); ++i)
    moved += a.objects[i].mesh.positions != b.objects[i].mesh.positions;
  return moved;
}

}  // namespace

// Played forward (each pose after the one before), then each pose alone after another scene
// (built from scratch): the same settings, bit for bit, in every field and reason.
TEST(AutoPerPose, SettingsAtAPoseEqualTheStaticPosedSceneFromScratch) {
  std::vector<std::string> warnings;
  for (const char* name : {"toys", "dragon_turntable"}) {
    const Scene animated = loadScene(name, warnings);
    ASSERT_FALSE(animated.animation.empty()) << name;
    const std::vector<double> times = {0.0, 0.4, 1.3, 2.9};
    std::vector<AutoSettings> played;
    for (double t : times) played.push_back(settingsFor(staticAt(animated, t), 160, 120));
    for (size_t i = 0; i < times.size(); ++i) {
      settingsFor(makeBuiltinScene("cube"), 160, 120);  // another scene in between
      const AutoSettingsWork before = autoSettingsWork();
      const AutoSettings alone = settingsFor(staticAt(animated, times[i]), 160, 120);
      EXPECT_EQ(autoSettingsWork().bvhBuilds, before.bvhBuilds + 1) << "from scratch";
      EXPECT_GT(alone.probes, 0) << name;
      expectSame(alone, played[i], std::string(name) + " at t = " + std::to_string(times[i]));
    }
  }
}

// What a pose costs: one Embree build and one analysis, whose rays are about one per probe
// point (about ten before the walks were bounded) where the light rays cross more than two
// occluder surfaces (the dragon: 8): once the first probes have counted the most the
// depth-complexity walk counts, no other probe walks, and the free gaps between occluders,
// which decide only at two surfaces or fewer, are not traced. The camera alone moving builds
// nothing.
TEST(AutoPerPose, APoseCostsOneBuildAndAboutOneRayPerProbePoint) {
  std::vector<std::string> warnings;
  const Scene animated = loadScene("dragon_turntable", warnings);
  const Scene first = staticAt(animated, 0), second = staticAt(animated, 0.5);
  ASSERT_GT(movedObjects(first, second), 0);
  // The probe points (auto_settings.h, step 1): 12 on every stride-th occluder triangle.
  size_t triangles = 0;
  for (const SceneObject& object : first.objects)
    if (!object.receiverOnly) triangles += object.mesh.triangleCount();
  const size_t stride = std::max<size_t>(1, 3 * triangles / kMaxProbes);
  const double points = 12.0 * double((triangles + stride - 1) / stride);

  settingsFor(makeBuiltinScene("cube"), 160, 120);
  AutoSettingsWork before = autoSettingsWork();
  for (const Scene* pose : {&first, &second}) {
    const AutoSettings chosen = settingsFor(*pose, 160, 120);
    const AutoSettingsWork after = autoSettingsWork();
    EXPECT_EQ(chosen.depthComplexity, 8);
    EXPECT_EQ(chosen.layers, 3);
    EXPECT_EQ(after.bvhBuilds - before.bvhBuilds, 1u);
    EXPECT_EQ(after.analyses - before.analyses, 1u);
    // One ray per point in front of the light, plus the first probes' walks.
    EXPECT_GT(double(after.rays - before.rays), 0.5 * points);
    EXPECT_LT(double(after.rays - before.rays), 1.1 * points);
    before = after;
  }
  // The camera alone: a new analysis of the same Embree scene.
  Scene turned = second;
  turned.camera.position.x += 0.5f;
  settingsFor(turned, 160, 120);
  const AutoSettingsWork after = autoSettingsWork();
  EXPECT_EQ(after.bvhBuilds, before.bvhBuilds);
  EXPECT_EQ(after.analyses, before.analyses + 1);
  // The same pose again (the same camera, light and size): the stored answer, no rays.
  settingsFor(turned, 160, 120);
  EXPECT_EQ(autoSettingsWork().analyses, after.analyses);
  EXPECT_EQ(autoSettingsWork().rays, after.rays);
}

// Where the free gaps decide (two plates one above the other: two surfaces on every light
// ray), they are traced: more rays than probe points.
TEST(AutoPerPose, FreeGapsAreTracedWhereTheyDecide) {
  std::vector<std::string> warnings;
  const Scene plates = loadScene(std::string(PENUMBRA_SOURCE_DIR) + "/assets/scenes/two_plates.json", warnings);
  const AutoSettingsWork before = autoSettingsWork();
  const AutoSettings chosen = settingsFor(plates, 256, 192);
  const AutoSettingsWork after = autoSettingsWork();
  ASSERT_LE(chosen.depthComplexity, 2);
  EXPECT_EQ(chosen.layers, 3);
  EXPECT_GT(chosen.separateOccluderProbes, 0);
  EXPECT_GT(double(after.rays - before.rays), 2.0 * chosen.probes);
}

// The light's frustum fitted to the casters (light.fov_degrees=auto,
// stages/shared_inputs/light/auto_frustum.h, docs/decisions/135): an occluder straddling the edge of
// the fixed 90-degree frustum shadows receivers outside it, which every depth-map method read
// as lit (decision 009). Oracles: the frustum's coverage by brute force (points along the
// shadow rays from the light's corners projected through the light's matrix), and the exact
// analytic visibility (support/analytic_visibility.h) on either side of the old edge.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <cstdlib>
#include <random>
#include <sstream>

#include "scene/light_frame.h"
#include "scene/mesh_builders.h"
#include "shared_inputs/light/auto_frustum.h"
#include "support/analytic_scenes.h"
#include "support/gl_test.h"

namespace {

// Inside the light's frustum (clip space of lightClipFromWorld), in front of its near plane.
bool insideFrustum(const LightFrame& light, const glm::dvec3& p, double slack) {
  const glm::dvec4 clip = glm::dmat4(light.lightClipFromWorld) * glm::dvec4(p, 1.0);
  if (clip.w <= 0) return false;
  return std::fabs(clip.x / clip.w) <= 1 + slack && std::fabs(clip.y / clip.w) <= 1 + slack;
}

// Every caster vertex's shadow from each light corner (c + s (c - L), s up to 1000) inside.
int uncoveredShadowPoints(const Scene& scene, const LightFrame& light) {
  const glm::dvec3 r = light.right, u = light.up;
  int outside = 0;
  for (const SceneObject& object : scene.objects) {
    if (object.receiverOnly) continue;
    for (const glm::vec3& vertex : object.mesh.positions)
      for (int corner = 0; corner < 4; ++corner) {
        const glm::dvec3 corner3 = glm::dvec3(scene.light.center) +
                                   (corner & 1 ? 0.5 : -0.5) * scene.light.width * r +
                                   (corner & 2 ? 0.5 : -0.5) * scene.light.height * u;
        const glm::dvec3 c(vertex);
        for (double s : {0.0, 0.5, 2.0, 10.0, 100.0, 1000.0})
          if (!insideFrustum(light, c + s * (c - corner3), 1e-4)) ++outside;
      }
  }
  return outside;
}

SceneObject quadAt(const std::string& name, float size, const glm::vec3& at, bool receiver) {
  return {name, makeQuad(size, glm::translate(glm::mat4(1), at)), glm::vec3(0.5f), receiver};
}

// A 1 x 1 light 3 above a receiver-only ground; a caster straddling the 90-degree frustum's
// side, so that part of its shadow on the ground lies outside it (the frustum reaches
// 0.5 + depth sideways).
Scene straddlingScene(const std::string& variant) {
  Scene scene;
  scene.name = "straddling_" + variant;
  scene.light = {{0, 3, 0}, {0, -1, 0}, {0, 0, -1}, 1.0f, 1.0f};
  scene.objects.push_back(quadAt("ground", 24, {0, 0, 0}, true));
  if (variant == "plate") {  // x in [1.5, 2.5] at depth 1.5: the edge at x = 2
    scene.objects.push_back(quadAt("plate", 1, {2.0f, 1.5f, 0}, false));
    scene.camera = {{3.6f, 4.2f, 4.5f}, {3.6f, 0.3f, 0}, {0, 1, 0}, 45};
  } else {  // a box 0.6 wide at depth 2.0-2.6, across the edge z = -(0.5 + depth)
    scene.objects.push_back({"box", makeBox({0.6f, 0.6f, 0.6f},
                                            glm::translate(glm::mat4(1), {0.4f, 0.7f, -2.6f})),
                             glm::vec3(0.8f, 0.4f, 0.3f), false});
    scene.camera = {{2.8f, 3.6f, -0.2f}, {0.4f, 0.2f, -3.9f}, {0, 1, 0}, 45};
  }
  return scene;
}

}  // namespace

// Random casters in front of a random rectangular light: with the fitted field of view every
// caster's shadow from every corner of the light is inside the frustum; with the fitted tangent
// 2% smaller (where it is over 90 degrees) some is not: the fit is as tight as it may be.
TEST(AutoFrustum, CoversEveryCastersShadowFromEveryPointOfTheLight) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(-1, 1);
  int widened = 0, covered = 0;
  for (int trial = 0; trial < 40; ++trial) {
    Scene scene;
    scene.name = "random";
    scene.light = {{0, 4, 0}, glm::normalize(glm::vec3(0.15f * unit(random), -1, 0.15f * unit(random))),
                   {0, 0, -1}, 0.5f + std::fabs(unit(random)), 0.5f + std::fabs(unit(random))};
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 at{2.5f * unit(random), 1.5f + unit(random), 2.5f * unit(random)};
      scene.objects.push_back(quadAt("caster" + std::to_string(k), 0.3f + 0.5f * std::fabs(unit(random)), at, false));
    }
    const FrustumFit fit = fitLightFrustum(scene, 150);
    if (!fit.uncovered.empty()) continue;  // beyond 150 degrees (counted below)
    ++covered;
    const LightFrame light = computeLightFrame(scene.light, scene.bounds(), float(fit.fovDegrees));
    EXPECT_EQ(uncoveredShadowPoints(scene, light), 0) << trial << " fov " << fit.fovDegrees;
    if (fit.neededDegrees > kAutoFovFloorDegrees) {
      ++widened;
      const double tighter = 2.0 * std::atan(0.98 * std::tan(fit.fovDegrees * M_PI / 360.0)) * 180.0 / M_PI;
      const LightFrame narrow = computeLightFrame(scene.light, scene.bounds(), float(tighter));
      EXPECT_GT(uncoveredShadowPoints(scene, narrow), 0) << trial << " fov " << fit.fovDegrees;
    }
  }
  EXPECT_GE(covered, 30);
  EXPECT_GE(widened, 10);  // the trials test the widening, not only the floor
}

TEST(AutoFrustum, NamesACasterThatReachesThroughTheLightPlane) {
  Scene scene = straddlingScene("plate");
  scene.objects.push_back({"pole", makeBox({0.1f, 2.0f, 0.1f}, glm::translate(glm::mat4(1), {-0.8f, 3.0f, 0})),
                           glm::vec3(0.5f), false});
  const FrustumFit fit = fitLightFrustum(scene, 150);
  ASSERT_EQ(fit.uncovered.size(), 1u);
  EXPECT_EQ(fit.uncovered[0], "pole");
  EXPECT_NE(fit.warning.find("'pole' reaches through the light's plane"), std::string::npos) << fit.warning;
  // The straddling plate alone: (|x| + w/2) / z = (2.5 + 0.5) / 1.5 = 2 across, 1 / 1.5 along.
  EXPECT_NEAR(fit.neededTanX, 2.0, 1e-5);
  EXPECT_NEAR(fit.neededTanY, 1.0 / 1.5, 1e-5);
  EXPECT_NEAR(fit.fovDegrees, 2 * std::atan(2.0) * 180 / M_PI, 1e-3);
  // The same warning reaches the run's auto reasons; a fixed 90 degrees is warned about too.
  PipelineRun run(scene, {"light.fov_degrees=90"}, 64, 48);
  bool warned = false;
  for (const std::string& reason : run.frame->autoReasons)
    warned = warned || reason.find("light.fov_degrees=90.0 is narrower than the 126.9") != std::string::npos;
  EXPECT_TRUE(warned);
}

// The straddling casters against the exact visibility, split at the old frustum's edge:
// at the fixed 90 degrees every depth-map method reads the outer part of the shadow as lit;
// with auto it is shadowed, as well outside the old edge as inside.
TEST(AutoFrustum, StraddlingCasterIsShadowedOnBothSidesOfTheOldEdge) {
  for (const std::string variant : {"plate", "box"}) {
    const Scene scene = straddlingScene(variant);
    double outsideAt90 = 1;
    for (const std::string fov : {"90", "auto"}) {
      std::vector<std::string> sets = {"light.fov_degrees=" + fov};
      // Measurements: PENUMBRA_FRUSTUM_SETS="stage.key=value ..." (not in CI).
      if (const char* extra = std::getenv("PENUMBRA_FRUSTUM_SETS")) {
        std::istringstream words(extra);
        for (std::string word; words >> word;) sets.push_back(word);
      }
      PipelineRun run(scene, sets, 256, 192);
      const std::vector<double> exact = analyticImage(run);
      const std::vector<float> positions = run.read("gbuffer.wsPosition");
      std::vector<double> inside(exact.size(), -1.0), outside(exact.size(), -1.0);
      for (size_t i = 0; i < exact.size(); ++i) {
        const double depth = 3.0 - positions[4 * i + 1];  // below the light plane
        const bool in = std::fabs(positions[4 * i]) <= 0.5 + depth &&
                        std::fabs(positions[4 * i + 2]) <= 0.5 + depth;
        (in ? inside : outside)[i] = exact[i];
      }
      std::printf("%-16s fov %-4s (%.1f):", scene.name.c_str(), fov.c_str(),
                  run.frame->counters["auto.fov_degrees"]);
      double filteredOutside = 0, filteredInside = 0;
      for (const char* output : {"filter.visibility", "trace.visibility", "pcss.visibility",
                                 "ssm.visibility", "hard_shadow.visibility"}) {
        const auto values = run.read(output);
        const AnalyticError in = compareWithAnalytic(values, inside);
        const AnalyticError out = compareWithAnalytic(values, outside);
        const AnalyticError all = compareWithAnalytic(values, exact);
        std::printf(" %s %.4f (in %.4f %+.4f %zu px, out %.4f %+.4f %zu px)", output, all.meanAbsInShadow,
                    in.meanAbsInShadow, in.meanSigned, in.pixelsInShadow, out.meanAbsInShadow,
                    out.meanSigned, out.pixelsInShadow);
        EXPECT_EQ(all.outOfRange, 0u) << output;
        EXPECT_GT(out.pixelsInShadow, 300u) << "the camera should see the shadow outside the old edge";
        if (output == std::string("filter.visibility")) {
          filteredOutside = out.meanAbsInShadow;
          filteredInside = in.meanAbsInShadow;
        }
      }
      std::printf("\n");
      for (const std::string& reason : run.frame->autoReasons) std::printf("  %s\n", reason.c_str());
      if (fov == "90") {
        EXPECT_GT(filteredOutside, 0.15) << scene.name << ": the defect this test is about";
        outsideAt90 = filteredOutside;
      } else {
        // No seam at the old edge: outside it the filtered result is as good as inside (what
        // is left is the method's error on this penumbra, not the frustum's), and a fifth of
        // what it was at 90 degrees (measured: 0.032 of it on the box, 0.044 on the plate).
        EXPECT_GT(run.frame->counters["auto.fov_degrees"], 100.0);
        EXPECT_LE(filteredOutside, filteredInside + 0.02) << scene.name;
        EXPECT_LE(filteredOutside, 0.2 * outsideAt90) << scene.name;
        EXPECT_LE(filteredInside, 0.05) << scene.name;
      }
    }
  }
}

namespace {

// A plate (a quad facing the light) straddling a side of the 90-degree frustum, under a light
// 3 above a receiver-only ground; the camera looks down at its shadow's centre.
struct Straddle {
  const char* name;
  float lightWidth, lightHeight, plateSize;
  glm::vec3 plateCentre;
};

Scene straddleScene(const Straddle& s) {
  Scene scene;
  scene.name = s.name;
  scene.light = {{0, 3, 0}, {0, -1, 0}, {0, 0, -1}, s.lightWidth, s.lightHeight};
  scene.objects.push_back(quadAt("ground", 40, {0, 0, 0}, true));
  scene.objects.push_back(quadAt("plate", s.plateSize, s.plateCentre, false));
  const glm::vec3 light = scene.light.center;
  const glm::vec3 shadow = light + (s.plateCentre - light) * (3.0f / (3.0f - s.plateCentre.y));
  const float reach = 2.0f + 3.0f * glm::length(glm::vec2(shadow.x, shadow.z)) / 3.0f;
  scene.camera = {shadow + glm::vec3(0, 1.1f * reach, 0.9f * reach), shadow, {0, 1, 0}, 45};
  return scene;
}

}  // namespace

// The straddling plate's penumbra beyond the old side: with the frustum widened, texel-sized
// offsets (the normal offset, thesis Eq 3.2's bias, the occluder's outline rounded to texels)
// grow with the texel, and the normal offset's shadow shift with the slant at which the rays
// reach the ground (tan 63 degrees = 2 at a 127-degree frustum's edge). Auto keeps the texels
// as small as at 90 degrees (docs/decisions/150), so the defaults meet the target on both
// sides of the old edge: filtered <= 0.03 mean |error| in shadow, and never worse than
// unfiltered by more than 0.005. Several placements: both axes, both signs, several depths and
// sizes, a square and a rectangular light.
TEST(AutoFrustum, StraddlingPlatesMeetTheTargetWithTheDefaults) {
  const Straddle cases[] = {
      {"plate_x_depth_1.5", 1, 1, 1.0f, {2.0f, 1.5f, 0}},
      {"plate_minus_z_depth_1.2", 1, 1, 1.0f, {0.3f, 1.8f, -1.7f}},
      {"plate_x_depth_2.0", 1, 1, 0.8f, {2.5f, 1.0f, 0.4f}},
      {"plate_minus_x_depth_0.8", 1, 1, 0.6f, {-1.3f, 2.2f, 0.5f}},
      {"rect_light_z_depth_1.5", 1.6f, 0.8f, 0.8f, {0, 1.5f, 1.15f}},
  };
  for (const Straddle& c : cases) {
    const Scene scene = straddleScene(c);
    std::vector<std::string> sets;  // measurements: PENUMBRA_FRUSTUM_SETS (not in CI)
    if (const char* extra = std::getenv("PENUMBRA_FRUSTUM_SETS")) {
      std::istringstream words(extra);
      for (std::string word; words >> word;) sets.push_back(word);
    }
    PipelineRun run(scene, sets, 256, 192);
    const LightFrame at90 = computeLightFrame(scene.light, scene.bounds(), 90.0f);
    const std::vector<double> exact = analyticImage(run);
    const std::vector<float> positions = run.read("gbuffer.wsPosition");
    std::vector<double> outside(exact.size(), -1.0);
    for (size_t i = 0; i < exact.size(); ++i)
      if (!insideFrustum(at90, {positions[4 * i], positions[4 * i + 1], positions[4 * i + 2]}, 0))
        outside[i] = exact[i];
    const auto filtered = run.read("filter.visibility"), traced = run.read("trace.visibility");
    const AnalyticError all = compareWithAnalytic(filtered, exact);
    const AnalyticError out = compareWithAnalytic(filtered, outside);
    const AnalyticError unfiltered = compareWithAnalytic(traced, exact);
    std::printf("%-24s fov %.1f map %.0f rays %.0f: filter %.4f (signed %+.4f; outside the 90-degree "
                "side %.4f %+.4f, %zu px of %zu), trace %.4f\n",
                c.name, run.frame->counters["auto.fov_degrees"], run.frame->counters["auto.resolution"],
                run.frame->counters["auto.rays_per_side"], all.meanAbsInShadow, all.meanSigned,
                out.meanAbsInShadow, out.meanSigned, out.pixelsInShadow, all.pixelsInShadow,
                unfiltered.meanAbsInShadow);
    EXPECT_GT(run.frame->counters["auto.fov_degrees"], 95.0) << c.name << ": the plate should straddle";
    EXPECT_GT(out.pixelsInShadow, 300u) << c.name << ": the camera should see the shadow beyond the side";
    EXPECT_LE(all.meanAbsInShadow, 0.03) << c.name;
    EXPECT_LE(out.meanAbsInShadow, 0.03) << c.name;
    EXPECT_LE(all.meanAbsInShadow, unfiltered.meanAbsInShadow + 0.005) << c.name;
  }
}

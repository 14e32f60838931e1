// Stage `ssm` (Atty et al. 2006) against exact visibility: a square plate parallel to the
// light and the ground (§4.2's "square plane"), two overlapping plates (overlaps bounded by
// Eq 3, §4.1.2), one pass against two, R32F against R16F, and finite visibility in [0, 1]
// on every built-in and stress scene. The oracle is tests/support/rect_visibility.h.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/mesh_builders.h"
#include "scene/scene_builtin.h"
#include "scene/scene_stress.h"
#include "support/gl_test.h"
#include "support/rect_visibility.h"

namespace {

RectLight rectLight(const Scene& scene, const LightFrame& frame) {
  return {glm::dvec3(scene.light.center), glm::dvec3(frame.right), glm::dvec3(frame.up),
          glm::dvec3(frame.forward), 0.5 * scene.light.width, 0.5 * scene.light.height};
}

// The receiver seen through the centre of soft-shadow-map texel (i, j): where the texel's
// ray from the projection point meets the ground plane y = 0 (the map's definition, Eq 3.1).
glm::dvec3 groundPointOfTexel(const LightFrame& f, int i, int j, int n) {
  const double x = ((i + 0.5) / n * 2 - 1) * f.tanHalfFovX, y = ((j + 0.5) / n * 2 - 1) * f.tanHalfFovY;
  const glm::dvec3 direction = glm::dvec3(f.forward) + x * glm::dvec3(f.right) + y * glm::dvec3(f.up);
  const glm::dvec3 origin(f.wsProjectionPoint);
  return origin + (-origin.y / direction.y) * direction;
}

// §4.1.1: the micro-patches tile the occluder up to half a texel at each edge. An edge moved
// by half a texel footprint (at the plate's depth) moves its back-projection by that times
// the scale (zR - zLight) / (zR - zPlate); the hidden fraction, a product of two overlaps in
// [0, 1], changes by at most the sum over the four edges.
double discretizationTolerance(const LightFrame& f, const Scene& scene, double plateZ,
                               double receiverZ, int n) {
  const double scale = (receiverZ - f.zNear) / (receiverZ - plateZ);
  const double halfTexelX = plateZ * f.tanHalfFovX / n, halfTexelY = plateZ * f.tanHalfFovY / n;
  return 2 * halfTexelX * scale / scene.light.width + 2 * halfTexelY * scale / scene.light.height;
}

double depthAlongLight(const LightFrame& f, const glm::dvec3& ws) {
  return glm::dot(ws - glm::dvec3(f.wsProjectionPoint), glm::dvec3(f.forward));
}

// `plate` with the plate and the light moved off the round numbers (so no sum is exact by
// luck) and a non-square light (the maps take its aspect ratio, §3.2).
const ParallelRect kPlate{{0.173, 1.05, -0.061}, 0.45, 0.45};

Scene plateScene() {
  Scene scene = makeBuiltinScene("plate");
  scene.objects[1].mesh = makeQuad(0.9f, glm::translate(glm::mat4(1), glm::vec3(kPlate.center)));
  scene.light.width = 1.2f;
  scene.light.height = 0.8f;
  return scene;
}

// The plate as the occluder map sees it (§3.2): the texels whose centre rays hit it, i.e.
// the plate with each edge moved to the nearest texel boundary at the plate's depth.
ParallelRect discretized(const LightFrame& f, const ParallelRect& plate, int n) {
  const glm::dvec3 rel = plate.center - glm::dvec3(f.wsProjectionPoint);
  const double z = glm::dot(rel, glm::dvec3(f.forward));
  const auto snap = [&](double centre, double half, double tanHalf) {
    const double texel = 2 * z * tanHalf / n;  // footprint at the plate's depth
    const double first = std::ceil((centre - half) / texel + 0.5 * n - 0.5);
    const double last = std::floor((centre + half) / texel + 0.5 * n - 0.5);
    return glm::dvec2((first - 0.5 * n) * texel, (last + 1 - 0.5 * n) * texel);
  };
  const glm::dvec2 x = snap(glm::dot(rel, glm::dvec3(f.right)), plate.halfWidth, f.tanHalfFovX);
  const glm::dvec2 y = snap(glm::dot(rel, glm::dvec3(f.up)), plate.halfHeight, f.tanHalfFovY);
  return {glm::dvec3(f.wsProjectionPoint) + z * glm::dvec3(f.forward) +
              0.5 * (x[0] + x[1]) * glm::dvec3(f.right) + 0.5 * (y[0] + y[1]) * glm::dvec3(f.up),
          0.5 * (x[1] - x[0]), 0.5 * (y[1] - y[0])};
}

struct PlateComparison {
  double largestError = 0, meanErrorInShadow = 0, tolerance = 0;
  double largestErrorDiscretized = 0;  // against the plate as the map sees it
  int shadowTexels = 0;
};

PlateComparison comparePlate(int n, const std::string& accumulation) {
  PipelineRun run(plateScene(), {"ssm.resolution=" + std::to_string(n),
                                           "ssm.accumulation=" + accumulation}, 64, 64);
  const LightFrame& f = run.frame->light;
  const RectLight light = rectLight(run.scene, f);
  const ParallelRect plate = kPlate;
  const ParallelRect seen = discretized(f, plate, n);
  const auto occlusion = run.read("ssm.softShadowMap");
  const auto receivers = run.read("ssm.receiverMap");
  const auto patches = run.read("ssm.patchCount");
  // Each blended addition rounds to the accumulation format: at most half an ulp of a sum
  // below 2, i.e. 2^-23 (r32f, 23-bit mantissa) or 2^-10 (r16f, 10 bits), per micro-patch.
  const double roundingPerPatch = accumulation == "r16f" ? std::ldexp(1.0, -10) : std::ldexp(1.0, -23);
  PlateComparison result;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (receivers[size_t(j * n + i)] >= 1.0f) continue;
      const glm::dvec3 receiver = groundPointOfTexel(f, i, j, n);
      const double exact = hiddenFraction(light, plate, receiver);
      const double ssm = occlusion[size_t(2 * (j * n + i))];
      const double error = std::abs(ssm - exact);
      const double errorDiscretized = std::abs(ssm - hiddenFraction(light, seen, receiver));
      EXPECT_LE(errorDiscretized, 1e-6 + roundingPerPatch * patches[size_t(j * n + i)])
          << "texel " << i << "," << j << ", " << accumulation;
      result.largestErrorDiscretized = std::max(result.largestErrorDiscretized, errorDiscretized);
      result.tolerance = discretizationTolerance(f, run.scene, depthAlongLight(f, plate.center),
                                                 depthAlongLight(f, receiver), n) +
                         1e-6 + roundingPerPatch * patches[size_t(j * n + i)];
      EXPECT_LE(error, result.tolerance) << "texel " << i << "," << j << " exact " << exact;
      result.largestError = std::max(result.largestError, error);
      if (exact > 0) result.meanErrorInShadow += error, ++result.shadowTexels;
    }
  result.meanErrorInShadow /= std::max(1, result.shadowTexels);
  return result;
}

}  // namespace

// The plate's micro-patches all lie at one depth, so their back-projections tile without
// overlap or gap (§4.1.2, dh = 0): the only error is the half-texel discretization (§4.1.1).
// Against the plate as the map sees it the soft shadow map is exact up to the rounding of the
// blended sums;
// against the true plate, within the half-texel bound, and it shrinks with the resolution.
TEST(Ssm, PlateMatchesExactVisibilityWithinHalfATexel) {
  const PlateComparison coarse = comparePlate(64, "r32f");
  const PlateComparison fine = comparePlate(256, "r32f");
  std::printf("plate, mean |occlusion error| over shadowed texels: 64^2 %.5f (largest %.5f, "
              "bound %.5f), 256^2 %.5f (largest %.5f, bound %.5f); against the discretized "
              "plate: largest %.2g, %.2g\n",
              coarse.meanErrorInShadow, coarse.largestError, coarse.tolerance,
              fine.meanErrorInShadow, fine.largestError, fine.tolerance,
              coarse.largestErrorDiscretized, fine.largestErrorDiscretized);
  EXPECT_GT(coarse.shadowTexels, 200);
  EXPECT_LT(fine.largestError, coarse.largestError);
}

// §4.1.2, Eq 1-3: where micro-patches at different depths are neighbours, their
// back-projections overlap (or leave a gap). Two plates, the upper one partly over the lower
// in the map: against the exact visibility of the plates as the maps see them (so the
// half-texel discretization drops out), the soft shadow map's accumulated occlusion exceeds
// it where patches overlap, by no more than the overlap strips of the upper plate's sides.
//
// Fig. 13 redone for our maps, which are seen from the projection point d behind the light
// centre (Eq 3.1): with depths z' from the light plane, a receiver at z'_R lying xi off a
// boundary ray (at its depth), the boundary at z'_O (deeper patch) and z'_O - dh back-projects
// to two points f(z'_O) xi and f(z'_O - dh) xi apart from the ray's foot on the light,
// f(z') = z' / (z'_R - z'): the overlap is
//   Eq 1:  |xi| z'_R dh / ((z'_R - z'_O)(z'_R - z'_O + dh)),
// and, with the shallower point inside the light (|foot + xi f| <= L/2, |foot| <= e),
//   Eq 3:  (L/2 + e) z'_R dh / ((z'_R - z'_O)(z'_O - dh)),
// the paper's bound when the boundary ray leaves the light centre (e = 0). Each side adds a
// strip of that width (Eq 1 at the receiver, never more than Eq 3) across at most the
// back-projected side: an overlap when the receiver lies outside the side's boundary ray
// (the deeper patch, beyond the side, is displaced more, towards the upper one), a gap when
// it lies inside.
TEST(Ssm, OverlappingOccludersExceedExactByAtMostEq3) {
  const ParallelRect upper{{0.21, 1.7, 0.13}, 0.25, 0.25}, lower{{0.0, 0.9, 0.0}, 0.5, 0.5};
  Scene scene = makeBuiltinScene("plate");
  scene.objects[1].mesh = makeQuad(1.0f, glm::translate(glm::mat4(1), glm::vec3(lower.center)));
  scene.objects.push_back({"upper plate", makeQuad(0.5f, glm::translate(glm::mat4(1),
                           glm::vec3(upper.center))), {0.9f, 0.5f, 0.3f}, false});
  scene.light.width = 1.2f;
  scene.light.height = 0.8f;
  const int n = 128;
  PipelineRun run(scene, {"ssm.resolution=" + std::to_string(n)}, 64, 64);
  const LightFrame& f = run.frame->light;
  const RectLight light = rectLight(run.scene, f);
  const ParallelRect upperSeen = discretized(f, upper, n), lowerSeen = discretized(f, lower, n);
  const auto occlusion = run.read("ssm.softShadowMap");
  const auto receivers = run.read("ssm.receiverMap");

  const double d = f.zNear, L[2] = {scene.light.width, scene.light.height};
  const double zUpper = depthAlongLight(f, upperSeen.center);  // from the projection point
  const double zLower = depthAlongLight(f, lowerSeen.center);
  const double dh = zLower - zUpper, zO = zLower - d;
  const glm::dvec3 rel = upperSeen.center - glm::dvec3(f.wsProjectionPoint);
  const double centre[2] = {glm::dot(rel, glm::dvec3(f.right)), glm::dot(rel, glm::dvec3(f.up))};
  const double half[2] = {upperSeen.halfWidth, upperSeen.halfHeight};
  // The hole the upper plate leaves in the lower one, as the map sees it.
  const ParallelRect hole{glm::dvec3(f.wsProjectionPoint) + (zLower / zUpper) * rel,
                          upperSeen.halfWidth * zLower / zUpper, upperSeen.halfHeight * zLower / zUpper};
  double largestExcess = 0, largestDeficit = 0, boundAtLargest = 0, largestEq3 = 0;
  int overlapTexels = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (receivers[size_t(j * n + i)] >= 1.0f) continue;
      const glm::dvec3 receiver = groundPointOfTexel(f, i, j, n);
      const glm::dvec3 toReceiver = receiver - glm::dvec3(f.wsProjectionPoint);
      const double lateral[2] = {glm::dot(toReceiver, glm::dvec3(f.right)),
                                 glm::dot(toReceiver, glm::dvec3(f.up))};
      const double zAbs = depthAlongLight(f, receiver), zR = zAbs - d;
      // Lengths of the sides' back-projections on the light, in light fractions.
      const LightRect a = backProject(light, upperSeen, receiver), b = backProject(light, hole, receiver);
      const double sideLength[2] = {  // a side along x (y = const) spans x, and vice versa
          std::max(intervalOverlap(a.x0, a.x1, 0, 1), intervalOverlap(b.x0, b.x1, 0, 1)),
          std::max(intervalOverlap(a.y0, a.y1, 0, 1), intervalOverlap(b.y0, b.y1, 0, 1))};
      double overlapBound = 0, gapBound = 0;  // in fractions of the light's area
      for (int axis = 0; axis < 2; ++axis)
        for (int sign = -1; sign <= 1; sign += 2) {
          const double side = centre[axis] + sign * half[axis];     // at depth zUpper
          const double xi = lateral[axis] - side * zAbs / zUpper;    // off the boundary ray
          const double foot = std::abs(side * d / zUpper);           // e
          const double eq1 = std::abs(xi) * zR * dh / ((zR - zO) * (zR - zO + dh));
          const double eq3 = (0.5 * L[axis] + foot) * zR * dh / ((zR - zO) * (zO - dh));
          EXPECT_LE(std::min(eq1, L[axis]), eq3 + 1e-9);
          largestEq3 = std::max(largestEq3, eq3 / L[axis]);
          const double strip = std::min({eq1, eq3, L[axis]}) / L[axis] * sideLength[1 - axis];
          (sign * xi > 0 ? overlapBound : gapBound) += strip;
        }
      const double exact = hiddenFractionOfUnion(light, upperSeen, lowerSeen, receiver);
      const double difference = occlusion[size_t(2 * (j * n + i))] - exact;
      EXPECT_LE(difference, overlapBound + 1e-3) << "texel " << i << "," << j;
      EXPECT_GE(difference, -gapBound - 1e-3) << "texel " << i << "," << j;
      if (difference > largestExcess) largestExcess = difference, boundAtLargest = overlapBound;
      largestDeficit = std::max(largestDeficit, -difference);
      overlapTexels += difference > 1e-3;
    }
  std::printf("two plates (dh = %.2f), 128^2: accumulated - exact occlusion up to %.4f (bound "
              "there %.4f; Eq 3 per side up to %.3f of the light), %d texels over by > 1e-3; "
              "largest gap %.4f\n", dh, largestExcess, boundAtLargest, largestEq3, overlapTexels,
              largestDeficit);
  EXPECT_GT(largestExcess, 0.01);  // the overlap is there to see
  EXPECT_GT(overlapTexels, 20);
}

// §3.5 and §4.2.3: a zero-thickness plate has the same nearest and farthest surfaces, so one
// and two passes agree exactly; on the cube the second pass (the farthest surfaces) can only
// add occlusion, since the passes merge by their maximum.
TEST(Ssm, TwoPassesEqualOneOnThePlateAndOnlyDarkenTheCube) {
  PipelineRun one(plateScene(), {"ssm.passes=one"}, 96, 96), two(plateScene(), {"ssm.passes=two"}, 96, 96);
  EXPECT_EQ(one.read("ssm.visibility"), two.read("ssm.visibility"));
  PipelineRun cubeOne(makeBuiltinScene("cube"), {"ssm.passes=one"}, 96, 96);
  PipelineRun cubeTwo(makeBuiltinScene("cube"), {"ssm.passes=two"}, 96, 96);
  const auto a = cubeOne.read("ssm.visibility"), b = cubeTwo.read("ssm.visibility");
  int darker = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_LE(b[i], a[i] + 1e-6f) << "pixel " << i;
    darker += b[i] < a[i] - 1e-3f;
  }
  std::printf("cube 96x96: two passes darken %d pixels\n", darker);
  EXPECT_GT(darker, 0);
}

// §4.1.3, Appendix A, Fig. 14: summing many small contributions in 16-bit floats loses them
// once the sum is large, more so at high resolution (smaller micro-patches).
TEST(Ssm, HalfFloatAccumulationLosesPrecisionAtHighResolution) {
  const PlateComparison full = comparePlate(512, "r32f");
  const PlateComparison half = comparePlate(512, "r16f");
  std::printf("plate 512^2, mean |occlusion error| over shadowed texels: r32f %.5f, r16f %.5f\n",
              full.meanErrorInShadow, half.meanErrorInShadow);
  EXPECT_GT(half.meanErrorInShadow, 2 * full.meanErrorInShadow);
}

// Finite visibility in [0, 1] everywhere, on every built-in and stress scene, with one and two
// passes; clamping is counted, not hidden.
TEST(Ssm, VisibilityIsFiniteAndInRangeOnEveryScene) {
  std::vector<std::string> names = builtinSceneNames();
  for (const std::string& stress : stressSceneNames()) names.push_back(stress);
  for (const std::string& name : names)
    for (const char* passes : {"one", "two"}) {
      PipelineRun run(isStressScene(name) ? makeStressScene(name) : makeBuiltinScene(name), {std::string("ssm.passes=") + passes,
                                               "ssm.resolution=128"}, 96, 96);
      int shadowed = 0;
      for (float v : run.read("ssm.visibility")) {
        ASSERT_TRUE(std::isfinite(v) && v >= 0.0f && v <= 1.0f) << name << " " << passes << ": " << v;
        shadowed += v < 1.0f;
      }
      std::printf("%-22s %s pass(es): %5d shadowed pixels, %4.0f clamped, %5.0f micro-patches\n",
                  name.c_str(), passes, shadowed, run.frame->counters["ssm.clampedPixels"],
                  run.frame->counters["ssm.patches"]);
    }
}

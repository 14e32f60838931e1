// Oracles for stage `classify` (thesis §3.6, Eq 3.3).
// - The ray walk (checkClassification): independent of the shader's region formula and of
//   the N-buffer: rays from a dense grid of points on the light (in world space) to each
//   receiver are walked texel by texel through the light layers (classify_ray_walk.h, exact
//   per ray). The light grid (32 x 32 points, corners included) is a finite sample of the
//   rays: it finds a non-conservative "lit" wherever the blocked part of the light is wider
//   than a grid cell, which the tests assert cannot happen.
// - ExactRegionClassifier (the hierarchy comparison) is NOT independent of the region
//   formula: it repeats reachableTexels (shaders/monte_carlo/classify/classify.glsl, Eq 3.3 / Fig 3.7) in
//   double precision without the 0.01-texel margin, because what it checks is the min/max
//   over that region: that the N-buffer and min-max hierarchies bound the exact brute-force
//   min/max over it. The region itself is checked by the ray walk above.
// - Both start from the receiver as the shader moves it (offsetReceiver mirrors bias.glsl's
//   capped normal offset), because the classification must be conservative at that point,
//   the one the trace starts from. Whether the offset itself is right is the analytic
//   suite's to check (AccuracyDefects.NormalOffsetKeepsContactShadowsAtCoarseMaps).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "classify_ray_walk.h"
#include "scene/mesh_builders.h"
#include "scene/scene_builtin.h"
#include "scene/scene_stress.h"
#include "shared/classes.h"
#include "support/gl_test.h"

namespace {

constexpr int kClassBackground = CLASS_BACKGROUND, kClassLit = CLASS_LIT,
              kClassPenumbra = CLASS_PENUMBRA, kClassUmbra = CLASS_UMBRA,
              kClassOutside = CLASS_OUTSIDE;

// The largest bias any of the trace's rays gets at a receiver at light depth z: light.bias
// plus Eq 3.2 with n.l at its clamp. A ray's end moves towards the light by its bias along
// the ray, so its depth lies in [z - largestBias, z].
double largestTraceBias(const PipelineRun& run, double z) {
  const Pipeline& pipeline = *run.pipeline;
  const LightFrame& light = run.frame->light;
  double bias = pipeline.param("light.bias").asFloat();
  if (pipeline.param("light.adaptive_bias").asBool())
    bias += std::sqrt(2.0) * z * std::max(light.tanHalfFovX, light.tanHalfFovY) /
            (run.frame->light.mapSize * double(pipeline.param("light.min_cosine").asFloat()));
  return bias;
}

// The point classify and the trace start from, a copy of shaders/shared/bias.glsl's capped
// normal offset (not an independent oracle of it): moved light.normal_offset texels along
// the normal, but towards the light by at most a quarter of the gap to the pixel's zNearMin
// (lsDepth, zRange.x) where that gap exceeds the Eq 3.2 bias. The checks here are about
// conservativeness at that point; the offset itself is checked against the analytic
// visibility in AccuracyDefects.NormalOffsetKeepsContactShadowsAtCoarseMaps.
glm::dvec3 offsetReceiver(const PipelineRun& run, const LightLayersOnCpu& layers,
                          const glm::dvec3& receiver, const glm::dvec3& normal, double zNearMin) {
  const LightFrame& light = run.frame->light;
  const double z = layers.toMap(receiver).z;
  const double texelWorld = 2.0 * z * std::max(light.tanHalfFovX, light.tanHalfFovY) / light.mapSize;
  double offset = run.pipeline->param("light.normal_offset").asFloat() * texelWorld;
  const double towardsLight = -glm::dot(normal, glm::dvec3(light.forward));
  const double gap = z - layers.toZ(zNearMin);
  const double ownSurface = run.pipeline->param("light.bias").asFloat() + std::sqrt(0.5) * texelWorld;
  if (towardsLight > 0 && gap > ownSurface) offset = std::min(offset, 0.25 * gap / towardsLight);
  return receiver + normal * offset;
}

struct Findings {
  int lit = 0, umbra = 0, penumbra = 0, outside = 0, background = 0;
  int litViolations = 0;          // lit pixels with a blocked ray (must be 0)
  int umbraOneLayerMisses = 0;    // umbra pixels with a ray that ends in front of the near layer
  int umbraTwoLayerMisses = 0;    // umbra pixels with a ray passing no near..far interval
  long umbraRaysMissingTwoLayer = 0, umbraRays = 0;
  std::string firstLitViolation, firstUmbraMiss;
};

// Checks every lit and umbra pixel of the run with 32 x 32 rays each.
Findings checkClassification(const PipelineRun& run) {
  const LightLayersOnCpu layers(run);
  const auto mask = run.read("classify.mask");
  const auto zRange = run.read("classify.zRange");
  const auto positions = run.read("gbuffer.wsPosition");
  const auto normals = run.read("gbuffer.wsNormal");
  const LightFrame& light = run.frame->light;
  const auto grid = lightGrid(run.scene, light, 32);
  const double tolerance = 1e-5 * (light.zFar - light.zNear);  // float rounding on the GPU
  Findings found;
  for (size_t i = 0; i < mask.size(); ++i) {
    const int pixelClass = int(mask[i]);
    if (pixelClass == kClassBackground) { ++found.background; continue; }
    if (pixelClass == kClassOutside) { ++found.outside; continue; }
    if (pixelClass == kClassPenumbra) { ++found.penumbra; continue; }
    const glm::dvec3 receiver = offsetReceiver(
        run, layers, {positions[i * 4], positions[i * 4 + 1], positions[i * 4 + 2]},
        {normals[i * 4], normals[i * 4 + 1], normals[i * 4 + 2]}, zRange[i * 4]);
    // The trace's rays end between these depths (shortened by the bias, thesis §3): "lit"
    // must hold for the longest ray, "umbra" for the shortest.
    const double z = layers.toMap(receiver).z;
    const double deepestEnd = z, shallowestEnd = z - largestTraceBias(run, z);
    const std::string where = "pixel (" + std::to_string(i % run.frame->eyeWidth) + ", " +
                              std::to_string(i / run.frame->eyeWidth) + ")";
    if (pixelClass == kClassLit) {
      ++found.lit;
      // Only depths where some occluder exists can block: [min near, max far] over the map.
      const double from = std::max(layers.zNear(), layers.occluderZMin() - tolerance);
      const double to = std::min(deepestEnd, layers.occluderZMax() + tolerance);
      for (const glm::dvec3& wsLight : grid) {
        const bool blocked = layers.walk(
            wsLight, receiver, from, to,
            [&](double nearZ, double farZ, bool occupied, double zIn, double zOut) {
              return occupied && nearZ < zOut - tolerance && farZ >= zIn;
            });
        if (blocked) {
          if (found.litViolations++ == 0) found.firstLitViolation = where;
          break;
        }
      }
    } else if (pixelClass == kClassUmbra) {
      ++found.umbra;
      bool oneLayerMiss = false;
      int twoLayerMisses = 0;
      for (const glm::dvec3& wsLight : grid) {
        bool oneLayerHit = false, twoLayerHit = false;
        layers.walk(wsLight, receiver, layers.zNear(), shallowestEnd,
                    [&](double nearZ, double farZ, bool occupied, double zIn, double zOut) {
                      // One layer (§3.2): anything behind the near layer is solid.
                      oneLayerHit = oneLayerHit || zOut >= nearZ - tolerance;
                      // Two layers (§3.3): solid between near and far.
                      twoLayerHit = twoLayerHit || (occupied && nearZ <= zOut + tolerance &&
                                                    farZ >= zIn - tolerance);
                      return oneLayerHit && twoLayerHit;
                    });
        oneLayerMiss = oneLayerMiss || !oneLayerHit;
        twoLayerMisses += !twoLayerHit;
      }
      found.umbraRays += long(grid.size());
      found.umbraRaysMissingTwoLayer += twoLayerMisses;
      found.umbraOneLayerMisses += oneLayerMiss;
      if (twoLayerMisses > 0 && found.umbraTwoLayerMisses++ == 0)
        found.firstUmbraMiss = where + ": " + std::to_string(twoLayerMisses) + " of " +
                               std::to_string(grid.size()) + " rays pass no occluder";
    }
  }
  return found;
}

// Two zero-thickness plates at different heights whose shadow-map images abut (both inner
// edges project to the map's center line), with a gap between them in space that rays from
// one side of the light pass through (see the test).
Scene stackedPlates() {
  Scene scene = makeBuiltinScene("plate");
  scene.name = "stacked plates";
  scene.objects.resize(1);  // keep the ground
  auto plate = [](float x0, float x1, float height) {
    glm::mat4 place = glm::translate(glm::mat4(1), {0.5f * (x0 + x1), height, 0});
    return makeQuad(1.0f, glm::scale(place, {x1 - x0, 1, 3}));
  };
  scene.objects.push_back({"upper plate", plate(-3.0f, 0.0f, 2.0f), {0.3f, 0.5f, 0.9f}, false});
  scene.objects.push_back({"lower plate", plate(0.0f, 3.0f, 0.5f), {0.9f, 0.5f, 0.3f}, false});
  scene.camera = {{0, 1.2f, 5}, {0, 0.2f, 0}, {0, 1, 0}, 45};
  return scene;
}

}  // namespace

namespace {

// The conservativeness checks on one scene at the default 512 x 512 map, classified over
// `hierarchy` (trace.hierarchy: nbuffer or minmax).
void checkScene(const std::string& name, const std::string& hierarchy = "nbuffer") {
  PipelineRun run(makeBuiltinScene(name), {"trace.hierarchy=" + hierarchy}, 256, 256);
  const Findings found = checkClassification(run);
  std::printf("[ %s, %s ] lit %d, penumbra %d, umbra %d, outside %d, background %d; umbra "
              "pixels with a ray that misses both layers' slabs: %d (%ld of %ld rays)\n",
              name.c_str(), hierarchy.c_str(), found.lit, found.penumbra, found.umbra,
              found.outside, found.background, found.umbraTwoLayerMisses,
              found.umbraRaysMissingTwoLayer, found.umbraRays);
  testing::Test::RecordProperty("umbraPixels", found.umbra);
  testing::Test::RecordProperty("umbraPixelsMissedTwoLayers", found.umbraTwoLayerMisses);
  // "Lit" must be exact: no ray from the light grid meets an occluder (§3.6, first rule).
  EXPECT_EQ(found.litViolations, 0) << "first: " << found.firstLitViolation;
  // "Umbra" is exact for the thesis's derivation, a single layer (behind near is solid).
  EXPECT_EQ(found.umbraOneLayerMisses, 0);
  // Classification does its job: most receivers need no rays, some do.
  EXPECT_GT(found.lit, found.penumbra) << name;
  EXPECT_GT(found.penumbra, 100) << name;

  // A lit pixel is lit in the hard shadow too: the ray through the light's center is one of
  // its rays, and hard_shadow shortens it (classify's lit test does not).
  const auto mask = run.read("classify.mask");
  const auto hard = run.read("hard_shadow.visibility");
  int litButHardShadowed = 0;
  for (size_t i = 0; i < mask.size(); ++i)
    litButHardShadowed += int(mask[i]) == kClassLit && hard[i] < 0.5f;
  EXPECT_EQ(litButHardShadowed, 0);
}

std::vector<int> classesOf(PipelineRun& run, int iterations) {
  EXPECT_EQ(run.pipeline->set("classify.iterations=" + std::to_string(iterations)), "");
  run.run();
  std::vector<int> classes;
  for (float value : run.read("classify.mask")) classes.push_back(int(value));
  return classes;
}

}  // namespace

TEST(Classify, LitIsConservativeCube) { checkScene("cube"); }
TEST(Classify, LitIsConservativeSpheres) { checkScene("spheres"); }
TEST(Classify, LitIsConservativePlate) { checkScene("plate"); }
TEST(Classify, LitIsConservativeOverTheMinMaxMipmap) {
  for (const char* name : {"cube", "spheres", "plate"}) checkScene(name, "minmax");
}

// Thesis §3.6 derives "z >= zNearMax: fully shadowed" for one depth layer. With two layers
// (solid only between near and far) it can fail where a nearer occluder's image abuts a
// farther one's in the map with no texel in common: here an upper plate (y = 2, x < 0) and
// a lower one (y = 0.5, x > 0). Every texel of the region holds an occluder nearer than the
// receiver, so the rule says umbra, yet rays from the light's +x side to ground points at
// x slightly below 0 cross x = 0 between the plates' heights: in front of the lower plate's
// texels, then behind the upper plate's. This documents the caveat with numbers; the trace
// stage, not classify, decides those pixels when the umbra rule is off.
TEST(Classify, TwoLayerUmbraRuleMissesRaysBetweenAbuttingOccluders) {
  // The settings the caveat is about, pinned: two layers (`auto` takes three here, the plates
  // being separate occluders along light rays: decision 116) and the 90-degree frustum the
  // case was built for (`auto` widens it to cover the upper plate from every light point,
  // decision 135, which moves the plates' images off the abutting texels).
  PipelineRun run(stackedPlates(), {"light.layers=two", "light.fov_degrees=90"}, 128, 128);
  const Findings found = checkClassification(run);
  std::printf("[ stacked plates ] umbra %d pixels, %d with rays that miss both plates in the "
              "two-layer model (%ld of %ld rays); lit %d, penumbra %d\n",
              found.umbra, found.umbraTwoLayerMisses, found.umbraRaysMissingTwoLayer,
              found.umbraRays, found.lit, found.penumbra);
  if (!found.firstUmbraMiss.empty()) std::printf("  e.g. %s\n", found.firstUmbraMiss.c_str());
  RecordProperty("umbraPixels", found.umbra);
  RecordProperty("umbraPixelsMissedTwoLayers", found.umbraTwoLayerMisses);
  EXPECT_EQ(found.litViolations, 0) << "first: " << found.firstLitViolation;
  EXPECT_EQ(found.umbraOneLayerMisses, 0);
  EXPECT_GT(found.umbra, 1000);
  EXPECT_GT(found.umbraTwoLayerMisses, 0) << "the two-layer caveat no longer shows: was the "
                                             "umbra rule made two-layer safe?";
}

// Every pixel gets exactly one class; the counters are the mask's histogram; the bounds are
// finite and ordered; outside and background follow the geometry; the mask and zRange agree.
TEST(Classify, CountersAddUpAndMatchTheMaskAndTheBounds) {
  const int width = 200, height = 150;  // not square: catches swapped axes
  PipelineRun run(makeBuiltinScene("spheres"), {"light.resolution=256"}, width, height);
  const auto mask = run.read("classify.mask");
  const auto zRange = run.read("classify.zRange");
  const auto positions = run.read("gbuffer.wsPosition");
  const auto normals = run.read("gbuffer.wsNormal");
  const LightLayersOnCpu layers(run);
  const LightFrame& light = run.frame->light;
  int histogram[5] = {0, 0, 0, 0, 0};
  for (size_t i = 0; i < mask.size(); ++i) {
    ASSERT_EQ(mask[i], std::round(mask[i])) << i;
    const int pixelClass = int(mask[i]);
    ASSERT_GE(pixelClass, 0);
    ASSERT_LE(pixelClass, 4);
    ++histogram[pixelClass];
    const float* bounds = &zRange[i * 4];
    for (int c = 0; c < 4; ++c) ASSERT_TRUE(std::isfinite(bounds[c])) << i;
    EXPECT_EQ(pixelClass == kClassBackground, positions[i * 4 + 3] == 0) << i;
    if (pixelClass == kClassBackground) continue;
    const glm::dvec3 receiver = offsetReceiver(
        run, layers, {positions[i * 4], positions[i * 4 + 1], positions[i * 4 + 2]},
        {normals[i * 4], normals[i * 4 + 1], normals[i * 4 + 2]}, bounds[0]);
    const glm::dvec3 map = layers.toMap(receiver);
    const double u = map.x / layers.width(), v = map.y / layers.height();
    const double margin = 1e-4;
    const bool clearlyInside = u > margin && u < 1 - margin && v > margin && v < 1 - margin &&
                               map.z > layers.zNear() * (1 + margin);
    const bool clearlyOutside = u < -margin || u > 1 + margin || v < -margin || v > 1 + margin;
    if (clearlyInside) {
      EXPECT_NE(pixelClass, kClassOutside) << i;
    }
    if (clearlyOutside) {
      EXPECT_EQ(pixelClass, kClassOutside) << i;
    }
    if (pixelClass == kClassOutside) continue;
    // zRange: zNearMin <= zNearMax, both in [0, 1]; w is the receiver's linear light depth.
    EXPECT_LE(bounds[0], bounds[1]) << i;
    EXPECT_GE(bounds[0], 0.0f);
    EXPECT_LE(bounds[1], 1.0f);
    const double lsDepth = (map.z - light.zNear) / (light.zFar - light.zNear);
    EXPECT_NEAR(bounds[3], lsDepth, 1e-5) << i;
    // Lit exactly when the receiver is not behind zNearMin; umbra only when even the
    // shortest ray ends behind zNearMax.
    if (pixelClass == kClassLit) {
      EXPECT_LE(lsDepth, bounds[0] + 1e-5) << i;
    } else {
      // Not lit: behind zNearMin, or part of the light behind the tangent plane.
      const glm::dvec3 normal{normals[i * 4], normals[i * 4 + 1], normals[i * 4 + 2]};
      const AreaLight& area = run.scene.light;
      const double spread = 0.5 * area.width * std::fabs(glm::dot(normal, glm::dvec3(light.right))) +
                            0.5 * area.height * std::fabs(glm::dot(normal, glm::dvec3(light.up)));
      const bool wholeLightInFront = glm::dot(normal, glm::dvec3(area.center) - receiver) - spread > 0;
      EXPECT_TRUE(lsDepth > bounds[0] - 1e-5 || !wholeLightInFront) << i;
    }
    if (pixelClass == kClassUmbra) {
      const double shallowestEnd = map.z - largestTraceBias(run, map.z);
      EXPECT_GE((shallowestEnd - light.zNear) / (light.zFar - light.zNear), bounds[1] - 1e-5) << i;
    }
  }
  const auto& counters = run.frame->counters;
  EXPECT_EQ(counters.at("classify.lit"), histogram[kClassLit]);
  EXPECT_EQ(counters.at("classify.penumbra"), histogram[kClassPenumbra]);
  EXPECT_EQ(counters.at("classify.umbra"), histogram[kClassUmbra]);
  EXPECT_EQ(counters.at("classify.outside"), histogram[kClassOutside]);
  EXPECT_EQ(counters.at("classify.lit") + counters.at("classify.penumbra") +
                counters.at("classify.umbra") + counters.at("classify.outside") +
                histogram[kClassBackground],
            double(width * height));
  EXPECT_GT(histogram[kClassOutside], 0);  // the ground reaches past the light's frustum
}

// The class and bounds are cleared to background (all 0) by a clear of the framebuffer the
// pass draws into (ScreenTriangle::clearAndDraw), and background fragments are discarded: a
// second run into the same textures, filled with a sentinel first, gives the same images.
TEST(Classify, BackgroundIsClearedInTexturesReused) {
  PipelineRun run(makeBuiltinScene("spheres"), {"light.resolution=128"}, 120, 90);
  const auto mask = run.read("classify.mask");
  const auto zRange = run.read("classify.zRange");
  ASSERT_GT(std::count(mask.begin(), mask.end(), float(kClassBackground)), 0);
  const float sentinel[4] = {-7, -7, -7, -7};
  glClearTexImage(run.frame->texture("classify.mask").id(), 0, GL_RED, GL_FLOAT, sentinel);
  glClearTexImage(run.frame->texture("classify.zRange").id(), 0, GL_RGBA, GL_FLOAT, sentinel);
  run.pipeline->run(*run.frame, {"classify.mask", "classify.zRange"});
  EXPECT_EQ(run.read("classify.mask"), mask);
  EXPECT_EQ(run.read("classify.zRange"), zRange);
}

namespace {

// Each iteration (Eq 3.3) only tightens the bounds: pixels move out of penumbra, never in.
// With no iteration the bounds are the whole map's (the coarsest N-buffer level, or the
// min-max mipmap's cells covering the map).
void checkIterationsOnlyTighten(const std::string& hierarchy) {
  PipelineRun run(makeBuiltinScene("cube"), {"light.resolution=256", "trace.hierarchy=" + hierarchy},
                  160, 160);
  std::vector<std::vector<int>> byIterations;
  for (int iterations = 0; iterations <= 4; ++iterations)
    byIterations.push_back(classesOf(run, iterations));
  std::vector<int> litCounts;
  for (int k = 0; k <= 4; ++k) {
    litCounts.push_back(int(std::count(byIterations[k].begin(), byIterations[k].end(), kClassLit)));
    if (k == 0) continue;
    int changedOtherwise = 0;
    for (size_t i = 0; i < byIterations[k].size(); ++i) {
      const int before = byIterations[k - 1][i], after = byIterations[k][i];
      changedOtherwise += before != after && before != kClassPenumbra;
    }
    EXPECT_EQ(changedOtherwise, 0) << "iterations " << k - 1 << " -> " << k;
  }
  std::printf("[ %s ] lit pixels with 0..4 iterations: %d %d %d %d %d\n", hierarchy.c_str(),
              litCounts[0], litCounts[1], litCounts[2], litCounts[3], litCounts[4]);
  EXPECT_GT(litCounts[2], litCounts[0] + 1000);  // refinement makes a real difference

  // Iterations 0: the whole-map bounds at every receiver in the map.
  classesOf(run, 0);
  const auto zRange = run.read("classify.zRange");
  const auto mask = run.read("classify.mask");
  const auto nearLayer = run.read("light_layers.near");
  const float nearMin = *std::min_element(nearLayer.begin(), nearLayer.end());
  const float nearMax = *std::max_element(nearLayer.begin(), nearLayer.end());
  for (size_t i = 0; i < mask.size(); ++i)
    if (int(mask[i]) != kClassBackground && int(mask[i]) != kClassOutside) {
      ASSERT_EQ(zRange[i * 4], nearMin) << i;
      ASSERT_EQ(zRange[i * 4 + 1], nearMax) << i;
    }
}

}  // namespace

TEST(Classify, MoreIterationsOnlyMovePixelsOutOfPenumbra) {
  checkIterationsOnlyTighten("nbuffer");
  checkIterationsOnlyTighten("minmax");
}

// §3.6: the umbra rule is invalid with three layers; the stage also has a switch for it.
TEST(Classify, NoUmbraWithThreeLayersOrWhenSwitchedOff) {
  PipelineRun run(makeBuiltinScene("plate"), {"light.resolution=256"}, 128, 128);
  const double lit = run.frame->counters.at("classify.lit");
  const double penumbra = run.frame->counters.at("classify.penumbra");
  const double umbra = run.frame->counters.at("classify.umbra");
  ASSERT_GT(umbra, 100);
  for (const char* assignment : {"classify.umbra=false", "light.layers=three"}) {
    PipelineRun changed(makeBuiltinScene("plate"),
                        {"light.resolution=256", std::string(assignment)}, 128, 128);
    EXPECT_EQ(changed.frame->counters.at("classify.umbra"), 0) << assignment;
    EXPECT_EQ(changed.frame->counters.at("classify.lit"), lit) << assignment;
    EXPECT_EQ(changed.frame->counters.at("classify.penumbra"), penumbra + umbra) << assignment;
  }
}

// The numerically hard scenes (grazing light, contact, zero-thickness sheet, light touching
// an occluder, far receiver, geometry outside the frustum): classification stays exact.
TEST(Classify, LitIsConservativeOnStressScenes) {
  for (const std::string& name : stressSceneNames()) {
    PipelineRun run(makeStressScene(name), {"light.resolution=256"}, 128, 128);
    const Findings found = checkClassification(run);
    std::printf("[ %s ] lit %d, penumbra %d, umbra %d, outside %d\n", name.c_str(), found.lit,
                found.penumbra, found.umbra, found.outside);
    EXPECT_EQ(found.litViolations, 0) << name << ", first: " << found.firstLitViolation;
    EXPECT_EQ(found.umbraOneLayerMisses, 0) << name;
  }
}

namespace {

// Eq 3.3 iterated on the CPU with exact bounds: at each iteration the closed square of
// Fig 3.7 at the current zNearMin, in texels, and min/max over every texel inside it, brute
// force (no hierarchy). Depths in linear light depth [0, 1], as the layers store them.
// The square is a copy of reachableTexels (shaders/monte_carlo/classify/classify.glsl) in double precision
// and without its 0.01-texel margin (which only grows the GPU's region): this oracle checks
// the hierarchies' min/max over the region, not the region (the ray walk checks that).
class ExactRegionClassifier {
public:
  explicit ExactRegionClassifier(const PipelineRun& run)
      : light_(run.frame->light), nearLs_(run.read("light_layers.near")),
        farLs_(run.read("light_layers.far")),
        width_(run.frame->texture("light_layers.near").width()),
        height_(run.frame->texture("light_layers.near").height()) {}

  // (min near, max near, max far) over texels [x0, x1] x [y0, y1].
  glm::dvec3 boundsOver(int x0, int y0, int x1, int y1) const {
    glm::dvec3 bounds{1, 0, 0};  // empty: near 1, far 0 (§3.3)
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const size_t i = size_t(y) * width_ + x;
        bounds = {std::min(bounds.x, double(nearLs_[i])), std::max(bounds.y, double(nearLs_[i])),
                  std::max(bounds.z, double(farLs_[i]))};
      }
    return bounds;
  }

  // The bounds classify reaches after `iterations` refinements for a receiver at map
  // coordinates `map` (texels x, y; linear depth z).
  glm::dvec3 bounds(const glm::dvec3& map, int iterations) const {
    const double n = light_.zNear, endLs = lsDepth(map.z);
    glm::dvec3 bounds = boundsOver(0, 0, width_ - 1, height_ - 1);
    for (int i = 0; i < iterations && endLs > bounds.x; ++i) {
      const double d = n + bounds.x * (light_.zFar - n);
      const double size = std::clamp(n * (map.z - d) / (d * (map.z - n)), 0.0, 1.0);
      const glm::dvec2 extent{width_, height_};
      const glm::dvec2 uv = glm::clamp(glm::dvec2(map) / extent, 0.0, 1.0);
      const glm::dvec2 lo = (1.0 - size) * uv * extent, hi = lo + size * extent;
      const glm::ivec2 last{width_ - 1, height_ - 1};
      const glm::ivec2 a = glm::clamp(glm::ivec2(glm::floor(lo)), glm::ivec2(0), last);
      const glm::ivec2 b = glm::clamp(glm::ivec2(glm::floor(hi)), glm::ivec2(0), last);
      const glm::dvec3 refined = boundsOver(a.x, a.y, b.x, b.y);
      bounds = {std::max(bounds.x, refined.x), std::min(bounds.y, refined.y),
                std::min(bounds.z, refined.z)};
    }
    return bounds;
  }

  double lsDepth(double z) const { return (z - light_.zNear) / (light_.zFar - light_.zNear); }

private:
  LightFrame light_;
  std::vector<float> nearLs_, farLs_;
  int width_, height_;
};

struct HierarchyComparison {
  int oraclePenumbra = 0, certainPenumbra = 0, nbufferPenumbra = 0, minmaxPenumbra = 0;
  int nbufferMissed = 0, minmaxMissed = 0;   // certain penumbra called lit or umbra (must be 0)
  int minmaxLitNotNbufferLit = 0, minmaxUmbraNotNbufferUmbra = 0;  // must be 0
  int otherClassesDiffer = 0;                // background / outside differ (must be 0)
  int visibilityDiffers = 0;  // trace.visibility differs where the N-buffer said lit/penumbra
};

// Classifies `scene` over both hierarchies and against the exact-region oracle. A pixel is
// "certainly penumbra" when the oracle's bounds leave it penumbra by more than float rounding
// (1e-5 in light depth, 1e-6 in the light-in-front test): neither hierarchy may call it lit
// or umbra. The GPU's region carries a 0.01-texel margin, so it only grows the region.
HierarchyComparison compareHierarchies(const Scene& scene, int mapSize, int cells, int width,
                                       int height) {
  const std::string resolution = "light.resolution=" + std::to_string(mapSize);
  PipelineRun nbuffer(scene, {resolution, "trace.hierarchy=nbuffer"}, width, height);
  PipelineRun minmax(scene, {resolution, "trace.hierarchy=minmax",
                             "classify.minmax_cells=" + std::to_string(cells)}, width, height);
  const ExactRegionClassifier oracle(nbuffer);
  const LightLayersOnCpu layers(nbuffer);
  const auto nbufferMask = nbuffer.read("classify.mask"), minmaxMask = minmax.read("classify.mask");
  const auto positions = nbuffer.read("gbuffer.wsPosition");
  const auto normals = nbuffer.read("gbuffer.wsNormal");
  const auto nbufferZRange = nbuffer.read("classify.zRange");  // its zNearMin caps the offset
  const auto nbufferVisibility = nbuffer.read("trace.visibility");
  const auto minmaxVisibility = minmax.read("trace.visibility");
  const int iterations = nbuffer.pipeline->param("classify.iterations").asInt();
  const bool umbraTest = nbuffer.pipeline->param("classify.umbra").asBool() &&
                         nbuffer.frame->light.layers < 3;
  const AreaLight& area = scene.light;
  const LightFrame& light = nbuffer.frame->light;
  const double tolerance = 1e-5;
  HierarchyComparison found;
  for (size_t i = 0; i < nbufferMask.size(); ++i) {
    const int byNbuffer = int(nbufferMask[i]), byMinmax = int(minmaxMask[i]);
    // Both searches are exact and the rays the same: a pixel lit by the N-buffer's bounds
    // and traced over the min-max mipmap sees the whole light. (Umbra is a heuristic with
    // two layers, so a traced umbra pixel may see some of it.)
    found.visibilityDiffers +=
        byNbuffer != kClassUmbra && nbufferVisibility[i] != minmaxVisibility[i];
    found.nbufferPenumbra += byNbuffer == kClassPenumbra;
    found.minmaxPenumbra += byMinmax == kClassPenumbra;
    found.minmaxLitNotNbufferLit += byMinmax == kClassLit && byNbuffer != kClassLit;
    found.minmaxUmbraNotNbufferUmbra += byMinmax == kClassUmbra && byNbuffer != kClassUmbra;
    const bool otherN = byNbuffer == kClassBackground || byNbuffer == kClassOutside;
    const bool otherM = byMinmax == kClassBackground || byMinmax == kClassOutside;
    if (otherN || otherM) {
      found.otherClassesDiffer += byNbuffer != byMinmax;
      continue;
    }
    const glm::dvec3 normal{normals[i * 4], normals[i * 4 + 1], normals[i * 4 + 2]};
    const glm::dvec3 receiver =
        offsetReceiver(nbuffer, layers, {positions[i * 4], positions[i * 4 + 1], positions[i * 4 + 2]},
                       normal, nbufferZRange[i * 4]);
    const glm::dvec3 map = layers.toMap(receiver);
    const glm::dvec3 bounds = oracle.bounds(map, iterations);
    const double endLs = oracle.lsDepth(map.z);
    const double shallowestEnd = oracle.lsDepth(map.z - largestTraceBias(nbuffer, map.z));
    const double spread = 0.5 * area.width * std::fabs(glm::dot(normal, glm::dvec3(light.right))) +
                          0.5 * area.height * std::fabs(glm::dot(normal, glm::dvec3(light.up)));
    const double inFront = glm::dot(normal, glm::dvec3(area.center) - receiver) - spread;
    const bool exactLit = endLs <= bounds.x && inFront > 0;
    found.oraclePenumbra += !exactLit && !(umbraTest && shallowestEnd >= bounds.y);
    const bool certainlyNotLit = endLs > bounds.x + tolerance || inFront < -1e-6;
    const bool certainlyNotUmbra = !umbraTest || shallowestEnd < bounds.y - tolerance;
    if (!(certainlyNotLit && certainlyNotUmbra)) continue;
    ++found.certainPenumbra;
    found.nbufferMissed += byNbuffer != kClassPenumbra;
    found.minmaxMissed += byMinmax != kClassPenumbra;
  }
  return found;
}

void checkMinMaxClassification(const std::string& name, int mapSize, int cells) {
  const HierarchyComparison found =
      compareHierarchies(makeBuiltinScene(name), mapSize, cells, 128, 128);
  std::printf("[ %s, map %d, %d x %d cells ] penumbra pixels: exact-region oracle %d (%d "
              "certain), N-buffer %d, min-max %d (%+d, %+.1f %%); certain penumbra called "
              "lit/umbra: N-buffer %d, min-max %d; trace.visibility differing (not umbra): %d\n",
              name.c_str(), mapSize, cells, cells, found.oraclePenumbra, found.certainPenumbra,
              found.nbufferPenumbra, found.minmaxPenumbra,
              found.minmaxPenumbra - found.nbufferPenumbra,
              100.0 * (found.minmaxPenumbra - found.nbufferPenumbra) / std::max(found.nbufferPenumbra, 1),
              found.nbufferMissed, found.minmaxMissed, found.visibilityDiffers);
  testing::Test::RecordProperty("nbufferPenumbra", found.nbufferPenumbra);
  testing::Test::RecordProperty("minmaxPenumbra", found.minmaxPenumbra);
  EXPECT_GT(found.certainPenumbra, 100) << name;  // the check has something to check
  EXPECT_EQ(found.nbufferMissed, 0) << name << ": the oracle disagrees with the exact N-buffer";
  EXPECT_EQ(found.minmaxMissed, 0) << name;
  EXPECT_EQ(found.minmaxLitNotNbufferLit, 0) << name;
  EXPECT_EQ(found.minmaxUmbraNotNbufferUmbra, 0) << name;
  EXPECT_EQ(found.otherClassesDiffer, 0) << name;
  EXPECT_GE(found.minmaxPenumbra, found.nbufferPenumbra) << name;
  // At most one pixel in a thousand of the N-buffer's penumbra (rounding where a shortened
  // ray starts; bench-hierarchy measured none before classification changed).
  EXPECT_LE(found.visibilityDiffers, found.nbufferPenumbra / 1000) << name;
}

}  // namespace

// Classification over the min-max mipmap (docs/decisions/026-classify-follows-trace-hierarchy.md)
// (2 x 2 aligned cells covering Eq 3.3's square) is conservative against brute-force min/max over
// the exact square: no pixel the exact bounds call penumbra becomes lit or umbra; some lit or umbra
// pixels become penumbra (counted), fewer with more cells per axis (classify.minmax_cells). A
// non-power-of-two map exercises odd level sizes.
TEST(Classify, MinMaxBoundsAreConservativeAgainstTheExactRegion) {
  for (int cells : {2, 4}) {
    checkMinMaxClassification("cube", 256, cells);
    checkMinMaxClassification("spheres", 200, cells);
    checkMinMaxClassification("plate", 256, cells);
  }
}

// Oracles for stage `classify` (thesis §3.6, Eq 3.3). Independent of the shader's region
// formula and of the N-buffer: rays from a dense grid of points on the light (in world
// space) to each receiver are walked texel by texel through the light layers.
//
// Why a texel walk: the layers are piecewise constant per texel, and along a ray 1/z is
// linear in the projected position (perspective), so an exact 2D grid traversal (DDA) gives
// every texel the ray's projection crosses together with the exact depth interval the ray
// spans inside it; a hit test per texel is then exact for that ray, with no sampling gaps.
// The light grid (32 x 32 points, corners included) is a finite sample of the rays: it can
// find a non-conservative "lit" wherever the blocked part of the light is wider than a
// grid cell, which is what the test asserts cannot happen.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "mesh_builders.h"
#include "scene_builtin.h"
#include "support/gl_test.h"

namespace {

constexpr int kClassBackground = 0, kClassLit = 1, kClassPenumbra = 2, kClassUmbra = 3,
              kClassOutside = 4;

// The frame's light layers and light frame, in linear depth z along the light axis.
class LightLayersOnCpu {
public:
  explicit LightLayersOnCpu(const PipelineRun& run)
      : light_(run.frame->light), nearLs_(run.read("light_layers.near")),
        farLs_(run.read("light_layers.far")) {
    const GlTexture& layer = run.frame->input("light_layers.near");
    width_ = layer.width();
    height_ = layer.height();
    double minNear = 1, maxFar = 0;
    for (size_t i = 0; i < nearLs_.size(); ++i)
      if (nearLs_[i] <= farLs_[i]) {  // an occupied texel (empty ones are near 1, far 0)
        minNear = std::min(minNear, double(nearLs_[i]));
        maxFar = std::max(maxFar, double(farLs_[i]));
      }
    occluderZMin_ = toZ(minNear);
    occluderZMax_ = toZ(maxFar);
  }

  double toZ(double lsDepth) const { return light_.zNear + lsDepth * (light_.zFar - light_.zNear); }
  double zNear() const { return light_.zNear; }
  double occluderZMin() const { return occluderZMin_; }
  double occluderZMax() const { return occluderZMax_; }

  // World -> (texel coordinates x, y in [0, W] x [0, H], z along the light axis), from the
  // light's view matrix and half-angles (the map spans x/z in [-tan, tan]).
  glm::dvec3 toMap(const glm::dvec3& ws) const {
    const glm::dvec4 view = glm::dmat4(light_.lightViewFromWorld) * glm::dvec4(ws, 1.0);
    const double z = -view.z;
    return {(0.5 + 0.5 * view.x / (z * light_.tanHalfFovX)) * width_,
            (0.5 + 0.5 * view.y / (z * light_.tanHalfFovY)) * height_, z};
  }

  // Walks the segment from the light point to the receiver, restricted to depths
  // [zFrom, zTo], texel by texel: visit(nearZ, farZ, occupied, zIn, zOut) per texel
  // crossed; stops early when visit returns true. Returns whether it stopped early.
  template <class Visit>
  bool walk(const glm::dvec3& wsLight, const glm::dvec3& wsReceiver, double zFrom, double zTo,
            Visit visit) const {
    const glm::dvec3 a = toMap(wsLight), b = toMap(wsReceiver);
    const double invA = 1.0 / a.z, invB = 1.0 / b.z;
    auto sAt = [&](double z) { return std::clamp((invA - 1.0 / z) / (invA - invB), 0.0, 1.0); };
    auto zAt = [&](double s) { return 1.0 / ((1.0 - s) * invA + s * invB); };
    const double s0 = sAt(zFrom), s1 = sAt(zTo);
    if (!(s0 < s1)) return false;
    const glm::dvec2 p0 = glm::dvec2(a) + s0 * glm::dvec2(b - a);
    const glm::dvec2 p1 = glm::dvec2(a) + s1 * glm::dvec2(b - a);
    // Amanatides-Woo traversal in texel units; t in [0, 1] runs from p0 to p1.
    int ix = int(std::floor(p0.x)), iy = int(std::floor(p0.y));
    const glm::dvec2 d = p1 - p0;
    const int stepX = d.x > 0 ? 1 : -1, stepY = d.y > 0 ? 1 : -1;
    const double inf = std::numeric_limits<double>::infinity();
    double tMaxX = d.x > 0 ? (ix + 1 - p0.x) / d.x : d.x < 0 ? (p0.x - ix) / -d.x : inf;
    double tMaxY = d.y > 0 ? (iy + 1 - p0.y) / d.y : d.y < 0 ? (p0.y - iy) / -d.y : inf;
    const double tDeltaX = d.x != 0 ? 1.0 / std::fabs(d.x) : inf;
    const double tDeltaY = d.y != 0 ? 1.0 / std::fabs(d.y) : inf;
    double t = 0;
    for (int guard = 0; guard < 4 * (width_ + height_) + 8; ++guard) {
      const double tNext = std::min({tMaxX, tMaxY, 1.0});
      const int x = std::clamp(ix, 0, width_ - 1), y = std::clamp(iy, 0, height_ - 1);
      const size_t i = size_t(y) * width_ + x;
      if (visit(toZ(nearLs_[i]), toZ(farLs_[i]), nearLs_[i] <= farLs_[i],
                zAt(s0 + t * (s1 - s0)), zAt(s0 + tNext * (s1 - s0))))
        return true;
      if (tNext >= 1.0) return false;
      if (tMaxX <= tMaxY) { ix += stepX; tMaxX += tDeltaX; }
      else { iy += stepY; tMaxY += tDeltaY; }
      t = tNext;
    }
    ADD_FAILURE() << "texel walk did not terminate";
    return false;
  }

  int width() const { return width_; }
  int height() const { return height_; }

private:
  LightFrame light_;
  std::vector<float> nearLs_, farLs_;
  int width_ = 0, height_ = 0;
  double occluderZMin_ = 0, occluderZMax_ = 0;
};

// World-space points of the light rectangle on an n x n grid, corners included.
std::vector<glm::dvec3> lightGrid(const Scene& scene, const LightFrame& light, int n) {
  std::vector<glm::dvec3> points;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double a = 2.0 * i / (n - 1) - 1, b = 2.0 * j / (n - 1) - 1;
      points.push_back(glm::dvec3(scene.light.center) +
                       a * 0.5 * scene.light.width * glm::dvec3(light.right) +
                       b * 0.5 * scene.light.height * glm::dvec3(light.up));
    }
  return points;
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
Findings checkClassification(const PipelineRun& run, float minCosine) {
  const LightLayersOnCpu layers(run);
  const auto mask = run.read("classify.mask");
  const auto positions = run.read("gbuffer.wsPosition");
  const auto normals = run.read("gbuffer.wsNormal");
  const LightFrame& light = run.frame->light;
  const auto grid = lightGrid(run.scene, light, 32);
  const double tanHalfFov = std::max(light.tanHalfFovX, light.tanHalfFovY);
  const double tolerance = 1e-5 * (light.zFar - light.zNear);  // float rounding on the GPU
  Findings found;
  for (size_t i = 0; i < mask.size(); ++i) {
    const int pixelClass = int(mask[i]);
    if (pixelClass == kClassBackground) { ++found.background; continue; }
    if (pixelClass == kClassOutside) { ++found.outside; continue; }
    if (pixelClass == kClassPenumbra) { ++found.penumbra; continue; }
    const glm::dvec3 receiver{positions[i * 4], positions[i * 4 + 1], positions[i * 4 + 2]};
    const glm::dvec3 normal{normals[i * 4], normals[i * 4 + 1], normals[i * 4 + 2]};
    // The rays end short of the receiver by the Eq 3.2 bias (thesis §3), as in the stage.
    const double z = layers.toMap(receiver).z;
    const double cosine = std::max(glm::dot(normal, -glm::dvec3(light.forward)), double(minCosine));
    const double zEnd = z - std::sqrt(2.0) * z * tanHalfFov / (layers.width() * cosine);
    const std::string where = "pixel (" + std::to_string(i % run.frame->eyeWidth) + ", " +
                              std::to_string(i / run.frame->eyeWidth) + ")";
    if (pixelClass == kClassLit) {
      ++found.lit;
      // Only depths where some occluder exists can block: [min near, max far] over the map.
      const double from = std::max(layers.zNear(), layers.occluderZMin() - tolerance);
      const double to = std::min(zEnd, layers.occluderZMax() + tolerance);
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
        layers.walk(wsLight, receiver, layers.zNear(), zEnd,
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

// Two zero-thickness plates at different heights whose shadow-map images overlap, with a
// gap between them that rays from one side of the light pass through (see the test).
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

// The conservativeness checks on one scene at the default 512 x 512 map.
void checkScene(const std::string& name) {
  PipelineRun run(makeBuiltinScene(name), {}, 256, 256);
  const Findings found = checkClassification(run, 0.1f);
  std::printf("[ %s ] lit %d, penumbra %d, umbra %d, outside %d, background %d; umbra pixels "
              "with a ray that misses both layers' slabs: %d (%ld of %ld rays)\n",
              name.c_str(), found.lit, found.penumbra, found.umbra, found.outside,
              found.background, found.umbraTwoLayerMisses, found.umbraRaysMissingTwoLayer,
              found.umbraRays);
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
  // its rays, and hard_shadow shortens it by more (a constant bias on top of Eq 3.2).
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

// Thesis §3.6 derives "z >= zNearMax: fully shadowed" for one depth layer. With two layers
// (solid only between near and far) it can fail where a nearer occluder's image abuts a
// farther one's in the map with no texel in common: here an upper plate (y = 2, x < 0) and
// a lower one (y = 0.5, x > 0). Every texel of the region holds an occluder nearer than the
// receiver, so the rule says umbra, yet rays from the light's +x side to ground points at
// x slightly below 0 cross x = 0 between the plates' heights: in front of the lower plate's
// texels, then behind the upper plate's. This documents the caveat with numbers; the trace
// stage, not classify, decides those pixels when the umbra rule is off.
TEST(Classify, TwoLayerUmbraRuleMissesRaysBetweenAbuttingOccluders) {
  PipelineRun run(stackedPlates(), {}, 128, 128);
  const Findings found = checkClassification(run, 0.1f);
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
  PipelineRun run(makeBuiltinScene("spheres"), {"light_layers.resolution=256"}, width, height);
  const auto mask = run.read("classify.mask");
  const auto zRange = run.read("classify.zRange");
  const auto positions = run.read("gbuffer.wsPosition");
  const auto normals = run.read("gbuffer.wsNormal");
  const LightLayersOnCpu layers(run);
  const LightFrame& light = run.frame->light;
  const double tanHalfFov = std::max(light.tanHalfFovX, light.tanHalfFovY);
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
    const glm::dvec3 receiver{positions[i * 4], positions[i * 4 + 1], positions[i * 4 + 2]};
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
    // Lit exactly when the biased end of the rays is not behind zNearMin.
    const glm::dvec3 normal{normals[i * 4], normals[i * 4 + 1], normals[i * 4 + 2]};
    const double cosine = std::max(glm::dot(normal, -glm::dvec3(light.forward)), 0.1);
    const double zEnd = map.z - std::sqrt(2.0) * map.z * tanHalfFov / (layers.width() * cosine);
    const double endLsDepth = (zEnd - light.zNear) / (light.zFar - light.zNear);
    if (pixelClass == kClassLit) {
      EXPECT_LE(endLsDepth, bounds[0] + 1e-5) << i;
    } else {
      EXPECT_GT(endLsDepth, bounds[0] - 1e-5) << i;
    }
    if (pixelClass == kClassUmbra) {
      EXPECT_GE(endLsDepth, bounds[1] - 1e-5) << i;
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

// Each iteration (Eq 3.3) only tightens the bounds: pixels move out of penumbra, never in.
// With no iteration the bounds are the whole map's, the coarsest N-buffer level.
TEST(Classify, MoreIterationsOnlyMovePixelsOutOfPenumbra) {
  PipelineRun run(makeBuiltinScene("cube"), {"light_layers.resolution=256"}, 160, 160);
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
  std::printf("lit pixels with 0..4 iterations: %d %d %d %d %d\n", litCounts[0], litCounts[1],
              litCounts[2], litCounts[3], litCounts[4]);
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

// §3.6: the umbra rule is invalid with three layers; the stage also has a switch for it.
TEST(Classify, NoUmbraWithThreeLayersOrWhenSwitchedOff) {
  PipelineRun run(makeBuiltinScene("plate"), {"light_layers.resolution=256"}, 128, 128);
  const double lit = run.frame->counters.at("classify.lit");
  const double penumbra = run.frame->counters.at("classify.penumbra");
  const double umbra = run.frame->counters.at("classify.umbra");
  ASSERT_GT(umbra, 100);
  for (const char* assignment : {"classify.umbra=false", "trace.layers=three"}) {
    PipelineRun changed(makeBuiltinScene("plate"),
                        {"light_layers.resolution=256", std::string(assignment)}, 128, 128);
    EXPECT_EQ(changed.frame->counters.at("classify.umbra"), 0) << assignment;
    EXPECT_EQ(changed.frame->counters.at("classify.lit"), lit) << assignment;
    EXPECT_EQ(changed.frame->counters.at("classify.penumbra"), penumbra + umbra) << assignment;
  }
}

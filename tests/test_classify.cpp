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
  scene.objects.push_back({"upper plate", plate(-3.0f, 0.2f, 2.0f), {0.3f, 0.5f, 0.9f}, false});
  scene.objects.push_back({"lower plate", plate(0.35f, 3.0f, 0.5f), {0.9f, 0.5f, 0.3f}, false});
  scene.camera = {{0, 1.2f, 5}, {0, 0.2f, 0}, {0, 1, 0}, 45};
  return scene;
}

}  // namespace

TEST(Classify, Scratch) {
  for (const char* name : {"cube", "spheres", "plate", "stacked"}) {
    PipelineRun run(std::string(name) == "stacked" ? stackedPlates() : makeBuiltinScene(name), {}, 256, 256);
    const Findings f = checkClassification(run, 0.1f);
    std::printf("%s: lit %d umbra %d penumbra %d outside %d bg %d | litViol %d (%s) umbra1 %d "
                "umbra2 %d (%s) rays %ld/%ld\n",
                name, f.lit, f.umbra, f.penumbra, f.outside, f.background, f.litViolations,
                f.firstLitViolation.c_str(), f.umbraOneLayerMisses, f.umbraTwoLayerMisses,
                f.firstUmbraMiss.c_str(), f.umbraRaysMissingTwoLayer, f.umbraRays);
  }
}

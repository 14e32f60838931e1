#include "soft_shadow_maps/ssm/ssm_cost.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

struct LightPoint {
  glm::vec2 uv;  // map coordinates, 0..1 across the light's frustum
  float z;       // distance along the light axis from the projection point
};

// Light view space: lookAt down -z; depth z = -view.z.
glm::vec3 toView(const LightFrame& light, const glm::vec3& p) {
  const glm::vec4 v = light.lightViewFromWorld * glm::vec4(p, 1.0f);
  return {v.x, v.y, -v.z};
}

LightPoint project(const LightFrame& light, const glm::vec3& v) {
  return {{v.x / (v.z * light.tanHalfFovX) * 0.5f + 0.5f, v.y / (v.z * light.tanHalfFovY) * 0.5f + 0.5f},
          v.z};
}

// The triangle clipped to z >= zNear (what the GPU's near plane keeps), as a fan.
int clipNear(const glm::vec3 in[3], float zNear, glm::vec3 out[4]) {
  int count = 0;
  for (int i = 0; i < 3; ++i) {
    const glm::vec3& a = in[i];
    const glm::vec3& b = in[(i + 1) % 3];
    const bool aIn = a.z >= zNear, bIn = b.z >= zNear;
    if (aIn) out[count++] = a;
    if (aIn != bIn) {
      const float t = (zNear - a.z) / (b.z - a.z);
      out[count++] = a + t * (b - a);
    }
  }
  return count;
}

class CoarseMaps {
public:
  explicit CoarseMaps(int cells) : cells_(cells), nearest_(size_t(cells) * cells, INFINITY),
                                   farthest_(size_t(cells) * cells, -INFINITY) {}

  // Rasterizes one projected triangle at the cell centres; 1/z is linear in map space.
  void add(const LightPoint p[3], bool receiver) {
    const glm::vec2 a = p[0].uv, b = p[1].uv, c = p[2].uv;
    const float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    const glm::vec2 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
    if (hi.x < 0 || hi.y < 0 || lo.x > 1 || lo.y > 1) return;
    const int x0 = std::max(0, int(std::floor(lo.x * cells_ - 0.5f)));
    const int y0 = std::max(0, int(std::floor(lo.y * cells_ - 0.5f)));
    const int x1 = std::min(cells_ - 1, int(std::ceil(hi.x * cells_ - 0.5f)));
    const int y1 = std::min(cells_ - 1, int(std::ceil(hi.y * cells_ - 0.5f)));
    bool covered = false;
    if (std::abs(area) > 0)
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const glm::vec2 q{(x + 0.5f) / cells_, (y + 0.5f) / cells_};
          const float w0 = ((b.x - q.x) * (c.y - q.y) - (c.x - q.x) * (b.y - q.y)) / area;
          const float w1 = ((c.x - q.x) * (a.y - q.y) - (a.x - q.x) * (c.y - q.y)) / area;
          const float w2 = 1.0f - w0 - w1;
          if (w0 < 0 || w1 < 0 || w2 < 0) continue;
          const float z = 1.0f / (w0 / p[0].z + w1 / p[1].z + w2 / p[2].z);
          record(x, y, z, receiver);
          covered = true;
        }
    if (!covered) {  // smaller than a cell: its first corner's cell, if on the map
      const glm::vec2 q = a * float(cells_);
      if (q.x >= 0 && q.y >= 0 && q.x < cells_ && q.y < cells_) record(int(q.x), int(q.y), p[0].z, receiver);
    }
  }

  int cells() const { return cells_; }
  float nearest(int i) const { return nearest_[i]; }
  float farthest(int i) const { return farthest_[i]; }
  float farthestReceiver() const { return farthestReceiver_; }

private:
  void record(int x, int y, float z, bool receiver) {
    if (receiver) {
      farthestReceiver_ = std::max(farthestReceiver_, z);
      return;
    }
    const size_t i = size_t(y) * cells_ + x;
    nearest_[i] = std::min(nearest_[i], z);
    farthest_[i] = std::max(farthest_[i], z);
  }

  int cells_;
  std::vector<float> nearest_, farthest_;
  float farthestReceiver_ = -INFINITY;
};

// Texels per side of the quad of a patch at depth z (the header's formula, plus the patch).
double quadSide(double n, double zLight, double zPatch, double zVirtual) {
  if (zPatch <= zLight) return 0;  // at or behind the light plane: nothing drawn
  const double fraction = zLight * std::max(0.0, zVirtual - zPatch) / ((zPatch - zLight) * zVirtual);
  return std::min(n, n * fraction + 1.0);
}

}  // namespace

SsmCostModel::SsmCostModel(const Scene& scene, const LightFrame& light) : zNear_(light.zNear) {
  CoarseMaps maps(kCells);
  for (const SceneObject& object : scene.objects) {
    const Mesh& mesh = object.mesh;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
      glm::vec3 view[3], clipped[4];
      for (int k = 0; k < 3; ++k) view[k] = toView(light, mesh.positions[mesh.indices[3 * t + k]]);
      const int count = clipNear(view, light.zNear, clipped);
      for (int k = 1; k + 1 < count; ++k) {
        const LightPoint p[3] = {project(light, clipped[0]), project(light, clipped[k]),
                                 project(light, clipped[k + 1])};
        maps.add(p, object.receiverOnly);
      }
    }
  }
  farthestReceiver_ = maps.farthestReceiver();
  for (int i = 0; i < kCells * kCells; ++i) {
    if (!std::isfinite(maps.nearest(i))) continue;
    nearest_.push_back(maps.nearest(i));
    farthest_.push_back(maps.farthest(i));
  }
}

SsmCostEstimate SsmCostModel::at(int n, int passes, double fill) const {
  SsmCostEstimate estimate;
  if (!std::isfinite(farthestReceiver_)) return estimate;  // no receiver: nothing drawn
  // Below 64 texels the cells are texels (cells of a finer grid each stand for a fraction).
  const double texelsPerCell = double(n) * n / (double(kCells) * kCells);
  double quadTexels = 0;
  for (size_t i = 0; i < nearest_.size(); ++i) {
    const double zVirtual = std::max<double>(farthestReceiver_, nearest_[i]);
    const double front = quadSide(n, zNear_, nearest_[i], zVirtual);
    estimate.patches += texelsPerCell;
    quadTexels += texelsPerCell * front * front;
    if (passes > 1) {
      const double back = quadSide(n, zNear_, farthest_[i],
                                   std::max<double>(farthestReceiver_, farthest_[i]));
      estimate.fragments += texelsPerCell * back * back;
    }
  }
  // A map coarser than the cells has no more patches than texels.
  estimate.patches = std::min(estimate.patches, double(n) * n);
  estimate.fragments = fill * (estimate.fragments + quadTexels);
  estimate.patches *= fill;
  estimate.meanQuadTexels = estimate.patches > 0 ? fill * quadTexels / estimate.patches : 0;
  return estimate;
}

SsmCostEstimate estimateSsmCost(const Scene& scene, const LightFrame& light, int n, int passes,
                                double fill) {
  return SsmCostModel(scene, light).at(n, passes, fill);
}

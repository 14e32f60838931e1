// A small exact ray-walk oracle for tests/stages/test_classify.cpp: the frame's light layers on
// the CPU and a texel-by-texel traversal of a world-space segment through them.
//
// Why a texel walk: the layers are piecewise constant per texel, and along a ray 1/z is
// linear in the projected position (perspective), so an exact 2D grid traversal (DDA,
// Amanatides & Woo) gives every texel the ray's projection crosses together with the exact
// depth interval the ray spans inside it; a hit test per texel is then exact for that ray,
// with no sampling gaps. Independent of the N-buffer and of Eq 3.3.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <limits>
#include <vector>

#include "support/gl_test.h"

// The frame's light layers and light frame, in linear depth z along the light axis.
class LightLayersOnCpu {
public:
  explicit LightLayersOnCpu(const PipelineRun& run)
      : light_(run.frame->light), nearLs_(run.read("light_layers.near")),
        farLs_(run.read("light_layers.far")) {
    const GlTexture& layer = run.frame->texture("light_layers.near");
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
inline std::vector<glm::dvec3> lightGrid(const Scene& scene, const LightFrame& light, int n) {
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

#include "support/layer_oracle_fetches.h"

#include <algorithm>
#include <cmath>

namespace {

constexpr double kDepthTie = 1e-5;  // lsDepth
constexpr double kEdgeTie = 1e-4;   // texels

// The texel holding p, clamped into the map; ambiguous when p lies near a texel edge.
glm::ivec2 texelOf(const LayerMaps& maps, glm::dvec2 p, bool& ambiguous) {
  for (int axis = 0; axis < 2; ++axis) {
    const double fraction = p[axis] - std::floor(p[axis]);
    if (fraction < kEdgeTie || fraction > 1 - kEdgeTie) ambiguous = true;
  }
  return glm::clamp(glm::ivec2(glm::floor(p)), glm::ivec2(0), glm::ivec2(maps.width - 1, maps.height - 1));
}

bool near(double a, double b) { return std::abs(a - b) < kDepthTie; }

}  // namespace

OracleEarlyOuts oracleEarlyOuts(const LayerMaps& maps, const OracleRay& ray, float zNear,
                                float zFar, double sStart, double sEnd, bool regionTest,
                                bool insideTest) {
  OracleEarlyOuts result;
  const RayDepth depth(ray, zNear, zFar);
  if (sStart > sEnd) {
    result.regionEmpty = true;  // nothing left of the ray: lit, nothing fetched
    return result;
  }
  if (regionTest) {
    result.fetches += 1;
    const glm::dvec2 p0 = rayPoint(ray, sStart), p1 = rayPoint(ray, sEnd);
    const glm::ivec2 lo = texelOf(maps, glm::min(p0, p1), result.ambiguous);
    const glm::ivec2 hi = texelOf(maps, glm::max(p0, p1), result.ambiguous);
    const int span = std::max(hi.x - lo.x, hi.y - lo.y) + 1;
    int side = 1;
    while (side < span) side *= 2;
    const glm::ivec2 size(maps.width, maps.height);
    glm::ivec2 start, end;
    for (int axis = 0; axis < 2; ++axis) {
      start[axis] = std::clamp(lo[axis], 0, std::max(size[axis] - side, 0));
      end[axis] = std::min(start[axis] + side, size[axis]);
    }
    double nearest = 1, farthest = 0;  // an empty window: near 1, far 0 (§3.3)
    for (int y = start.y; y < end.y; ++y)
      for (int x = start.x; x < end.x; ++x) {
        nearest = std::min<double>(nearest, maps.nearAt({x, y}));
        farthest = std::max<double>(farthest, maps.farAt({x, y}));
      }
    const double depthIn = depth.at(sStart), depthOut = depth.at(sEnd);
    if (near(depthOut, nearest) || near(depthIn, farthest)) result.ambiguous = true;
    result.regionEmpty = depthOut < nearest || depthIn > farthest;
    if (result.regionEmpty) return result;
  }
  if (insideTest) {
    result.fetches += 2;
    const glm::ivec2 texel = texelOf(maps, rayPoint(ray, sEnd), result.ambiguous);
    const double endDepth = depth.at(sEnd), n = maps.nearAt(texel), f = maps.farAt(texel);
    if (near(endDepth, n) || near(endDepth, f)) result.ambiguous = true;
    result.inside = n <= endDepth && endDepth <= f;
  }
  return result;
}

OracleSearch oracleLinearSearch(const LayerMaps& maps, const OracleRay& ray, float zNear,
                                float zFar, double sStart, double sEnd, double stepTexels,
                                int maxSteps) {
  OracleSearch result;
  const RayDepth depth(ray, zNear, zFar);
  const double length = glm::length(glm::dvec2(ray.texelB - ray.texelA)) * (sEnd - sStart);
  const double exactSteps = length / stepTexels;
  if (std::abs(exactSteps - std::round(exactSteps)) < 1e-4 && exactSteps > 0.5) result.ambiguous = true;
  const int steps = std::clamp(int(std::ceil(exactSteps)), 1, maxSteps);
  const double ds = (sEnd - sStart) / steps;
  glm::ivec2 previousTexel{-1, -1};
  bool previousInFront = false;
  for (int k = 0; k <= steps; ++k) {
    const double s = k == 0 ? sStart : sStart + k * ds;
    const glm::ivec2 texel = texelOf(maps, rayPoint(ray, s), result.ambiguous);
    const double d = depth.at(s), n = maps.nearAt(texel), f = maps.farAt(texel);
    result.fetches += 2;
    ++result.samples;
    const bool holds = n <= f;  // an empty texel (near > far) holds nothing
    if (holds && (near(d, n) || near(d, f))) result.ambiguous = true;
    const bool inFront = holds && d < n, behind = holds && d > f;
    const bool between = holds && !inFront && !behind;
    const bool crossed = k > 0 && texel == previousTexel && previousInFront && behind;
    if (between || crossed) {
      result.blocked = true;
      return result;
    }
    previousTexel = texel;
    previousInFront = inFront;
  }
  return result;
}

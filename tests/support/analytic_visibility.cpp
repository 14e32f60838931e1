#include "support/analytic_visibility.h"

#include <algorithm>
#include <cmath>

namespace {

using Polygon2 = std::vector<glm::dvec2>;

double cross2(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

// 1. Sutherland-Hodgman against the half-space value(x) >= 0 (value affine along edges).
template <typename Point, typename Value>
std::vector<Point> clipHalfSpace(const std::vector<Point>& polygon, Value value) {
  std::vector<Point> out;
  const size_t count = polygon.size();
  for (size_t i = 0; i < count; ++i) {
    const Point& a = polygon[i];
    const Point& b = polygon[(i + 1) % count];
    const double va = value(a), vb = value(b);
    if (va >= 0) out.push_back(a);
    if ((va >= 0) != (vb >= 0)) out.push_back(a + (b - a) * (va / (va - vb)));
  }
  return out;
}

double shoelace(const Polygon2& polygon) {
  double twice = 0;
  for (size_t i = 0; i < polygon.size(); ++i)
    twice += cross2(polygon[i], polygon[(i + 1) % polygon.size()]);
  return 0.5 * std::fabs(twice);
}

// Counter-clockwise order (the clip's inside test assumes it).
Polygon2 counterClockwise(Polygon2 polygon) {
  double twice = 0;
  for (size_t i = 0; i < polygon.size(); ++i)
    twice += cross2(polygon[i], polygon[(i + 1) % polygon.size()]);
  if (twice < 0) std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

// 2. Clips a polygon to a convex counter-clockwise region, edge by edge.
Polygon2 clipConvex(Polygon2 polygon, const Polygon2& region) {
  for (size_t i = 0; i < region.size() && polygon.size() >= 3; ++i) {
    const glm::dvec2 a = region[i], edge = region[(i + 1) % region.size()] - a;
    polygon = clipHalfSpace(polygon, [&](const glm::dvec2& x) { return cross2(edge, x - a); });
  }
  return polygon.size() >= 3 ? polygon : Polygon2{};
}

// The cross-section {y : (x, y) in polygon} of a convex polygon at x: [lo, hi], or empty.
bool crossSection(const Polygon2& polygon, double x, double& lo, double& hi) {
  lo = 1e300;
  hi = -1e300;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    if ((a.x < x && b.x < x) || (a.x > x && b.x > x) || a.x == b.x) continue;
    const double y = a.y + (b.y - a.y) * ((x - a.x) / (b.x - a.x));
    lo = std::min(lo, y);
    hi = std::max(hi, y);
  }
  return lo < hi;
}

}  // namespace

double unionArea(const std::vector<Polygon2>& polygonsIn) {
  std::vector<Polygon2> polygons;
  for (const Polygon2& polygon : polygonsIn)
    if (polygon.size() >= 3 && shoelace(polygon) > 0) polygons.push_back(polygon);
  if (polygons.empty()) return 0;
  if (polygons.size() == 1) return shoelace(polygons[0]);
  // 3. Events: vertices and the crossings of any two edges of different polygons.
  std::vector<double> events;
  for (const Polygon2& polygon : polygons)
    for (const glm::dvec2& v : polygon) events.push_back(v.x);
  for (size_t i = 0; i < polygons.size(); ++i)
    for (size_t j = i + 1; j < polygons.size(); ++j)
      for (size_t e = 0; e < polygons[i].size(); ++e)
        for (size_t f = 0; f < polygons[j].size(); ++f) {
          const glm::dvec2 a = polygons[i][e], b = polygons[i][(e + 1) % polygons[i].size()];
          const glm::dvec2 c = polygons[j][f], d = polygons[j][(f + 1) % polygons[j].size()];
          const double denominator = cross2(b - a, d - c);
          if (denominator == 0) continue;
          const double t = cross2(c - a, d - c) / denominator;
          const double u = cross2(c - a, b - a) / denominator;
          if (t >= 0 && t <= 1 && u >= 0 && u <= 1) events.push_back(a.x + t * (b.x - a.x));
        }
  std::sort(events.begin(), events.end());
  // 4. Per slab: the union of the cross-sections at the midpoint, times the width.
  double area = 0;
  std::vector<std::pair<double, double>> intervals;
  for (size_t k = 0; k + 1 < events.size(); ++k) {
    const double width = events[k + 1] - events[k];
    if (width <= 0) continue;
    const double x = 0.5 * (events[k] + events[k + 1]);
    intervals.clear();
    for (const Polygon2& polygon : polygons) {
      double lo, hi;
      if (crossSection(polygon, x, lo, hi)) intervals.push_back({lo, hi});
    }
    std::sort(intervals.begin(), intervals.end());
    double covered = 0, reach = -1e300;
    for (const auto& [lo, hi] : intervals) {
      if (hi <= reach) continue;
      covered += hi - std::max(lo, reach);
      reach = hi;
    }
    area += covered * width;
  }
  return area;
}

double analyticVisibility(const AnalyticLight& light, const std::vector<ConvexPolygon>& occluders,
                          const glm::dvec3& p, const glm::dvec3& n) {
  const glm::dvec3 f = glm::cross(light.right, light.up);
  const double pToPlane = glm::dot(f, light.center - p);
  const double lightArea = 4 * light.halfWidth * light.halfHeight;
  if (std::fabs(pToPlane) < 1e-300) return 0;  // in the light's plane: sees it edge-on
  // 1. R: the light rectangle (a, b) minus what lies behind the tangent plane:
  //    n . (c + a r + b u - p) > 0 is affine in (a, b).
  Polygon2 region = {{-light.halfWidth, -light.halfHeight}, {light.halfWidth, -light.halfHeight},
                     {light.halfWidth, light.halfHeight}, {-light.halfWidth, light.halfHeight}};
  const double n0 = glm::dot(n, light.center - p), na = glm::dot(n, light.right),
               nb = glm::dot(n, light.up);
  region = clipHalfSpace(region, [&](const glm::dvec2& x) { return n0 + na * x.x + nb * x.y; });
  if (region.size() < 3) return 0;
  const double regionArea = shoelace(region);
  // 2. Each occluder: the part strictly between p and the light plane, projected from p.
  std::vector<Polygon2> shadows;
  for (const ConvexPolygon& polygon : occluders) {
    auto h = [&](const glm::dvec3& q) { return glm::dot(f, q - p) / pToPlane; };
    const double kEdge = 1e-12;  // a point at p itself hides nothing
    ConvexPolygon inside =
        clipHalfSpace(polygon, [&](const glm::dvec3& q) { return h(q) - kEdge; });
    inside = clipHalfSpace(inside, [&](const glm::dvec3& q) { return 1.0 - h(q); });
    if (inside.size() < 3) continue;
    Polygon2 projected;
    for (const glm::dvec3& q : inside) {
      const glm::dvec3 onPlane = p + (q - p) / h(q);
      projected.push_back({glm::dot(light.right, onPlane - light.center),
                           glm::dot(light.up, onPlane - light.center)});
    }
    Polygon2 clipped = clipConvex(counterClockwise(projected), counterClockwise(region));
    if (!clipped.empty()) shadows.push_back(std::move(clipped));
  }
  const double hidden = std::min(unionArea(shadows), regionArea);
  return std::clamp((regionArea - hidden) / lightArea, 0.0, 1.0);
}

double rayCastVisibility(const AnalyticLight& light, const std::vector<ConvexPolygon>& occluders,
                         const glm::dvec3& p, const glm::dvec3& n, int m) {
  int visible = 0;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const double a = (2 * (i + 0.5) / m - 1) * light.halfWidth;
      const double b = (2 * (j + 0.5) / m - 1) * light.halfHeight;
      const glm::dvec3 sample = light.center + a * light.right + b * light.up;
      if (glm::dot(n, sample - p) <= 0) continue;
      bool blocked = false;
      for (const ConvexPolygon& polygon : occluders) {
        // Segment-plane crossing, then inside test: same side of every edge.
        const glm::dvec3 normal =
            glm::cross(polygon[1] - polygon[0], polygon[2] - polygon[0]);
        const double d0 = glm::dot(normal, p - polygon[0]), d1 = glm::dot(normal, sample - polygon[0]);
        if ((d0 > 0) == (d1 > 0) || d0 == 0 || d1 == 0) continue;
        const glm::dvec3 x = p + (sample - p) * (d0 / (d0 - d1));
        bool inside = true;
        for (size_t e = 0; e < polygon.size() && inside; ++e) {
          const glm::dvec3 edge = polygon[(e + 1) % polygon.size()] - polygon[e];
          inside = glm::dot(glm::cross(edge, x - polygon[e]), normal) >= 0;
        }
        if (inside) { blocked = true; break; }
      }
      visible += !blocked;
    }
  return double(visible) / (double(m) * m);
}

AnalyticLight analyticLight(const AreaLight& light) {
  AnalyticLight out;
  const glm::dvec3 forward = glm::normalize(glm::dvec3(light.forward));
  out.center = light.center;
  out.right = glm::normalize(glm::cross(forward, glm::dvec3(light.up)));
  out.up = glm::cross(out.right, forward);
  out.halfWidth = 0.5 * light.width;
  out.halfHeight = 0.5 * light.height;
  return out;
}

std::vector<ConvexPolygon> occluderTriangles(const Scene& scene) {
  std::vector<ConvexPolygon> triangles;
  for (const SceneObject& object : scene.objects) {
    if (object.receiverOnly) continue;
    const Mesh& mesh = object.mesh;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
      triangles.push_back({glm::dvec3(mesh.positions[mesh.indices[t]]),
                           glm::dvec3(mesh.positions[mesh.indices[t + 1]]),
                           glm::dvec3(mesh.positions[mesh.indices[t + 2]])});
  }
  return triangles;
}

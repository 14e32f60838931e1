// Exact visibility of a rectangular area light from a point through convex planar polygons
// (docs/accuracy.md), independent of the renderer: no depth map, no sampling, no GL, no Embree.
//
// THE GEOMETRY
// - The light is the rectangle c + a r + b u, |a| <= halfWidth, |b| <= halfHeight (r, u
//   orthonormal). A light point L is seen from the receiver p when the open segment (p, L)
//   meets no occluder and L lies in front of p's tangent plane (n . (L - p) > 0: an opaque
//   surface does not see through itself, as the reference and the trace's backface test).
// - An occluder point q blocks the light point p + (q - p) / h(q), where
//   h(q) = f . (q - p) / f . (c - p) (f the light plane's normal) is the fraction of the way
//   from p to the light plane. Only the part of a polygon with 0 < h < 1 can block, so each
//   polygon is clipped to that slab first; the central projection of the clipped convex
//   polygon is a convex polygon in the light's (a, b) plane.
// - visibility = area(R) - area(R n union of projections)) / area(light), with R the light
//   rectangle clipped to the tangent half-plane (convex). Each projection is clipped to R
//   (Sutherland-Hodgman); the union's area comes from a sweep in a: between consecutive
//   events (every vertex's a and every crossing of two edges) each polygon's cross-section
//   is one interval with ends affine in a, their order does not change, so the union's length
//   is affine in a and the midpoint rule is exact per slab. All in double.
// A box is six convex quads; a mesh's triangles are convex polygons too.
#pragma once
#include <glm/glm.hpp>

#include <vector>

#include "scene/scene.h"

struct AnalyticLight {
  glm::dvec3 center{0}, right{1, 0, 0}, up{0, 0, 1};  // right, up orthonormal
  double halfWidth = 0.5, halfHeight = 0.5;
};

using ConvexPolygon = std::vector<glm::dvec3>;  // planar, convex, in order

// Exact visible fraction of the light from p (normal n, unit).
double analyticVisibility(const AnalyticLight& light, const std::vector<ConvexPolygon>& occluders,
                          const glm::dvec3& p, const glm::dvec3& n);

// The same by brute force: an m x m grid of cell centres, each segment tested against each
// polygon (the oracle's own check).
double rayCastVisibility(const AnalyticLight& light, const std::vector<ConvexPolygon>& occluders,
                         const glm::dvec3& p, const glm::dvec3& n, int m);

// The scene's light (right = normalize(cross(forward, up)) as scene/light_frame.cpp, up made
// orthogonal), and every triangle of every object that casts shadows.
AnalyticLight analyticLight(const AreaLight& light);
std::vector<ConvexPolygon> occluderTriangles(const Scene& scene);

// Area of the union of convex 2D polygons (exposed for its own test).
double unionArea(const std::vector<std::vector<glm::dvec2>>& polygons);

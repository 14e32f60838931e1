#include "scene/scene_checks.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

#include "base/input_error.h"

namespace {

constexpr const char* kDepthMapMethods = "the depth-map methods (hard_shadow, classify, trace)";

// The light's frame: u along width, v along up (height), d along forward.
struct LightCoordinates {
  glm::dvec3 center, right, up, forward;
  double halfWidth, halfHeight;
  glm::dvec3 operator()(const glm::vec3& p) const {
    const glm::dvec3 q = glm::dvec3(p) - center;
    return {glm::dot(q, right), glm::dot(q, up), glm::dot(q, forward)};
  }
};

// 1. Does the segment a-b (light coordinates, on the light's plane) meet the rectangle?
//    Liang-Barsky clipping against |u| <= halfWidth, |v| <= halfHeight.
bool segmentMeetsRectangle(glm::dvec2 a, glm::dvec2 b, double halfWidth, double halfHeight) {
  double t0 = 0, t1 = 1;
  const glm::dvec2 d = b - a;
  const double p[4] = {-d.x, d.x, -d.y, d.y};
  const double q[4] = {a.x + halfWidth, halfWidth - a.x, a.y + halfHeight, halfHeight - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  return true;
}

// 2. A triangle with corners strictly on both sides of the light's plane that cuts the
//    rectangle: the light's plane runs through the occluder at the light.
bool crossesLight(const LightCoordinates& light, const glm::dvec3 corner[3]) {
  glm::dvec2 cut[2];
  int cuts = 0;
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3& a = corner[i];
    const glm::dvec3& b = corner[(i + 1) % 3];
    if ((a.z > 0) == (b.z > 0) || a.z == 0 || b.z == 0) continue;
    const double t = a.z / (a.z - b.z);
    if (cuts < 2) cut[cuts++] = glm::dvec2(a + t * (b - a));
  }
  return cuts == 2 && segmentMeetsRectangle(cut[0], cut[1], light.halfWidth, light.halfHeight);
}

// 3. Is the light's centre inside a closed mesh? Crossings of six rays from it (odd =
//    inside): three directions and their opposites, so an open sheet on one side (hit one
//    way, not the other) is not "inside", and at least five must agree, so a ray through
//    an edge does not decide alone.
bool enclosesCenter(const LightCoordinates& light, const Mesh& mesh) {
  const glm::dvec3 axes[3] = {glm::normalize(glm::dvec3(0.5773, 0.5774, 0.5775)),
                              glm::normalize(glm::dvec3(-0.3, 0.8, -0.52)),
                              glm::normalize(glm::dvec3(0.71, -0.6, 0.37))};
  int inside = 0;
  for (int ray = 0; ray < 6; ++ray) {
    const glm::dvec3 direction = ray < 3 ? axes[ray] : -axes[ray - 3];
    int crossings = 0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {  // Moller-Trumbore
      const glm::dvec3 a = mesh.positions[mesh.indices[3 * t]];
      const glm::dvec3 e1 = glm::dvec3(mesh.positions[mesh.indices[3 * t + 1]]) - a;
      const glm::dvec3 e2 = glm::dvec3(mesh.positions[mesh.indices[3 * t + 2]]) - a;
      const glm::dvec3 p = glm::cross(direction, e2);
      const double det = glm::dot(e1, p);
      if (std::abs(det) < 1e-300) continue;
      const glm::dvec3 s = light.center - a;
      const double u = glm::dot(s, p) / det;
      if (u < 0 || u > 1) continue;
      const glm::dvec3 q = glm::cross(s, e1);
      const double v = glm::dot(direction, q) / det;
      if (v < 0 || u + v > 1) continue;
      if (glm::dot(e2, q) / det > 0) ++crossings;
    }
    inside += crossings % 2;
  }
  return inside >= 5;
}

// 4. A triangle lying in the light's plane (every corner within `eps` of it) that overlaps
//    the rectangle: the light sits on that surface.
bool liesInLightPlane(const LightCoordinates& light, const glm::dvec3 corner[3], double eps) {
  for (int i = 0; i < 3; ++i)
    if (std::abs(corner[i].z) > eps) return false;
  for (int i = 0; i < 3; ++i)
    if (segmentMeetsRectangle(glm::dvec2(corner[i]), glm::dvec2(corner[(i + 1) % 3]), light.halfWidth,
                              light.halfHeight))
      return true;
  // The rectangle inside the triangle: its centre (the origin) on the inner side of all edges.
  double sign = 0;
  for (int i = 0; i < 3; ++i) {
    const glm::dvec2 a(corner[i]), b(corner[(i + 1) % 3]);
    const double side = (b.x - a.x) * (0 - a.y) - (b.y - a.y) * (0 - a.x);
    if (side * sign < 0) return false;
    if (side != 0) sign = side;
  }
  return sign != 0;
}

}  // namespace

std::vector<std::string> lightWarnings(const Scene& scene) {
  const AreaLight& l = scene.light;
  LightCoordinates light;
  light.center = l.center;
  light.forward = glm::normalize(glm::dvec3(l.forward));
  light.up = glm::normalize(glm::dvec3(l.up));
  light.right = glm::normalize(glm::cross(light.forward, light.up));
  light.halfWidth = 0.5 * l.width;
  light.halfHeight = 0.5 * l.height;

  std::vector<std::string> warnings;
  bool occluders = false, occluderInFront = false, anythingInFront = false;
  for (const SceneObject& object : scene.objects) {
    const Mesh& mesh = object.mesh;
    bool inFront = false;
    for (const glm::vec3& p : mesh.positions) inFront = inFront || light(p).z > 0;
    anythingInFront = anythingInFront || inFront;
    const std::string named = std::string(1, '\'').append(printable(object.name)).append("'");
    if (object.receiverOnly) {
      // A receiver in the light's plane, or cut by the light's rectangle: part of the light
      // is on or behind its surface. The reference shadows that part; the depth-map methods
      // and SSM (which see the surface at the light's plane, clipped) do not.
      const double eps = 1e-4 * std::max(light.halfWidth, light.halfHeight);
      bool inPlane = false;
      for (size_t t = 0; t < mesh.triangleCount() && !inPlane; ++t) {
        const glm::dvec3 corner[3] = {light(mesh.positions[mesh.indices[3 * t]]),
                                      light(mesh.positions[mesh.indices[3 * t + 1]]),
                                      light(mesh.positions[mesh.indices[3 * t + 2]])};
        inPlane = liesInLightPlane(light, corner, eps) || crossesLight(light, corner);
      }
      if (inPlane)
        warnings.push_back("the light's rectangle lies in or cuts through the plane of receiver " + named +
                           ": part of the light is on or behind that surface, which the reference "
                           "shadows and " + kDepthMapMethods + " and ssm do not (they show more "
                           "light than the reference)");
      continue;
    }
    occluders = true;
    occluderInFront = occluderInFront || inFront;
    const std::string name = std::string(1, '\'').append(printable(object.name)).append("'");
    bool crosses = false;
    for (size_t t = 0; t < mesh.triangleCount() && !crosses; ++t) {
      const glm::dvec3 corner[3] = {light(mesh.positions[mesh.indices[3 * t]]),
                                    light(mesh.positions[mesh.indices[3 * t + 1]]),
                                    light(mesh.positions[mesh.indices[3 * t + 2]])};
      crosses = crossesLight(light, corner);
    }
    if (crosses)
      warnings.push_back("the light's rectangle cuts through occluder " + name + ": " +
                         kDepthMapMethods + " clip it at the light's plane and show less shadow "
                         "than the reference");
    else if (enclosesCenter(light, mesh))
      warnings.push_back("the light sits inside occluder " + name + ": " + kDepthMapMethods +
                         " clip it at the light's plane and show less shadow than the reference");
  }
  if (!anythingInFront)
    warnings.insert(warnings.begin(), "the light faces away from all geometry: nothing lies on "
                                      "its emitting side, so nothing is lit");
  else if (occluders && !occluderInFront)
    warnings.insert(warnings.begin(),
                    std::string("the light faces away from every occluder: ") + kDepthMapMethods +
                        " see nothing in the light's depth maps and show no shadow, while the "
                        "reference (which lights both sides) shows shadows");
  return warnings;
}

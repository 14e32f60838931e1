#include "scene/eye_frustum.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

namespace {

// Sutherland-Hodgman against plane . (x, 1) >= 0.
void clip(std::vector<glm::vec3>& polygon, const glm::vec4& plane, std::vector<glm::vec3>& scratch) {
  scratch.clear();
  for (size_t i = 0; i < polygon.size(); ++i) {
    const glm::vec3& a = polygon[i];
    const glm::vec3& b = polygon[(i + 1) % polygon.size()];
    const float va = glm::dot(glm::vec3(plane), a) + plane.w;
    const float vb = glm::dot(glm::vec3(plane), b) + plane.w;
    if (va >= 0) scratch.push_back(a);
    if ((va >= 0) != (vb >= 0)) scratch.push_back(a + (b - a) * (va / (va - vb)));
  }
  polygon.swap(scratch);
}

}  // namespace

EyeDepthRange eyeDepthRange(const Scene& scene, float aspect) {
  const Camera& camera = scene.camera;
  const glm::mat4 viewFromWorld = glm::lookAt(camera.position, camera.target, camera.up);
  const float tanY = std::tan(glm::radians(camera.fovYDegrees) * 0.5f), tanX = tanY * aspect;
  // 1. The pyramid in view space (looking down -z; depth d = -z): |x| <= tanX d,
  //    |y| <= tanY d, d >= 0. Planes as (n, w) with n . p + w >= 0 inside.
  const glm::vec4 planes[5] = {{-1, 0, -tanX, 0}, {1, 0, -tanX, 0}, {0, -1, -tanY, 0},
                               {0, 1, -tanY, 0},  {0, 0, -1, 0}};
  float nearest = INFINITY, farthest = 0;
  std::vector<glm::vec3> polygon, scratch;
  for (const SceneObject& object : scene.objects) {
    const Mesh& mesh = object.mesh;
    std::vector<glm::vec3> viewPositions(mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i)
      viewPositions[i] = glm::vec3(viewFromWorld * glm::vec4(mesh.positions[i], 1));
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      polygon = {viewPositions[mesh.indices[t]], viewPositions[mesh.indices[t + 1]],
                 viewPositions[mesh.indices[t + 2]]};
      // 2. Clip (most triangles are wholly inside or outside one plane: cheap).
      for (const glm::vec4& plane : planes) {
        if (polygon.empty()) break;
        clip(polygon, plane, scratch);
      }
      for (const glm::vec3& p : polygon) {
        nearest = std::min(nearest, -p.z);
        farthest = std::max(farthest, -p.z);
      }
    }
  }
  EyeDepthRange range;
  const float distance = glm::length(camera.target - camera.position);
  if (!(farthest > 0) || !std::isfinite(nearest)) {
    range.eyeNear = 0.01f * distance;
    range.eyeFar = 100.0f * distance;
    return range;
  }
  // 3. The margin: depth is exact at the plane's distance; 10% keeps rounding inside.
  range.seesGeometry = true;
  range.eyeFar = 1.1f * farthest;
  range.eyeNear = std::max(0.9f * nearest, 1e-5f * range.eyeFar);
  return range;
}

EyeDepthRange eyeDepthRangeOrWarn(const Scene& scene, float aspect) {
  static bool warned = false;
  const EyeDepthRange range = eyeDepthRange(scene, aspect);
  if (!range.seesGeometry && !warned)
    std::fprintf(stderr,
                 "WARNING: scene '%s': the camera sees no geometry (no triangle inside its view); "
                 "the image will be empty. Check camera.position/target.\n",
                 scene.name.c_str());
  warned = !range.seesGeometry;
  return range;
}

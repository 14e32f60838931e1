#include "scene/scene.h"

#include <cmath>
#include <cstdio>

#include "base/input_error.h"

Bounds Scene::bounds(bool occludersOnly) const {
  Bounds result;
  for (const SceneObject& object : objects)
    if (!occludersOnly || !object.receiverOnly)
      for (const glm::vec3& p : object.mesh.positions) result.extend(p);
  return result;
}

size_t Scene::triangleCount() const {
  size_t count = 0;
  for (const SceneObject& object : objects) count += object.mesh.triangleCount();
  return count;
}

namespace {
bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool representable(const glm::vec3& v) {
  return std::abs(v.x) <= kMaxCoordinate && std::abs(v.y) <= kMaxCoordinate &&
         std::abs(v.z) <= kMaxCoordinate;
}

std::string outOfRange(const std::string& what, const glm::vec3& v) {
  char text[200];
  std::snprintf(text, sizeof text,
                "%s (%g, %g, %g) is out of range: coordinates must be within +-%g (the GPU "
                "computes in single precision and Embree rejects larger rays); scale the scene down",
                what.c_str(), v.x, v.y, v.z, kMaxCoordinate);
  return text;
}
}  // namespace

std::string validateScene(const Scene& scene) {
  if (scene.objects.empty()) return "scene '" + printable(scene.name) + "' has no objects";
  if (scene.objects.size() > kMaxSceneObjects)
    return std::to_string(scene.objects.size()) + " objects: more than the scene budget of " +
           std::to_string(kMaxSceneObjects);
  if (scene.triangleCount() > kMaxSceneTriangles)
    return std::to_string(scene.triangleCount()) + " triangles: more than the scene budget of " +
           std::to_string(kMaxSceneTriangles);
  for (const SceneObject& object : scene.objects) {
    const Mesh& mesh = object.mesh;
    const std::string where = "object '" + printable(object.name) + "': ";
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0)
      return where + "index count " + std::to_string(mesh.indices.size()) +
             " is not a positive multiple of 3";
    if (mesh.normals.size() != mesh.positions.size())
      return where + "normal count differs from position count";
    for (std::uint32_t index : mesh.indices)
      if (index >= mesh.positions.size())
        return where + "index " + std::to_string(index) + " out of range (" +
               std::to_string(mesh.positions.size()) + " vertices)";
    for (const glm::vec3& p : mesh.positions) {
      if (!finite(p)) return where + "non-finite vertex position";
      if (!representable(p)) return where + outOfRange("vertex", p);
    }
    for (const glm::vec3& n : mesh.normals)
      if (!finite(n)) return where + "non-finite normal";
  }
  const AreaLight& light = scene.light;
  if (!finite(light.center) || !finite(light.forward) || !finite(light.up))
    return "light: non-finite center, forward or up";
  if (!(light.width > 0 && light.height > 0) || !std::isfinite(light.width) ||
      !std::isfinite(light.height))
    return "light: width and height must be positive and finite";
  if (!representable(light.center)) return "light: " + outOfRange("center", light.center);
  if (light.width > 2 * kMaxCoordinate || light.height > 2 * kMaxCoordinate)
    return "light: width and height must be at most " + std::to_string(int(2 * kMaxCoordinate));
  if (glm::length(light.forward) < 1e-6f || glm::length(light.up) < 1e-6f ||
      glm::length(glm::cross(light.forward, light.up)) < 1e-3f * glm::length(light.forward) *
                                                              glm::length(light.up))
    return "light: forward and up must be non-zero and not parallel";
  const Camera& camera = scene.camera;
  if (!finite(camera.position) || !finite(camera.target) || !finite(camera.up) ||
      glm::length(camera.target - camera.position) < 1e-6f)
    return "camera: position and target must be finite and distinct";
  if (!representable(camera.position)) return "camera: " + outOfRange("position", camera.position);
  if (!representable(camera.target)) return "camera: " + outOfRange("target", camera.target);
  if (!(camera.fovYDegrees > 1 && camera.fovYDegrees < 179))
    return "camera: fovY must be in (1, 179) degrees";
  return "";
}

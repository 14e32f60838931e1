#include "scene/scene.h"

#include <cmath>

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
}  // namespace

std::string validateScene(const Scene& scene) {
  if (scene.objects.empty()) return "scene '" + scene.name + "' has no objects";
  for (const SceneObject& object : scene.objects) {
    const Mesh& mesh = object.mesh;
    const std::string where = "object '" + object.name + "': ";
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0)
      return where + "index count " + std::to_string(mesh.indices.size()) +
             " is not a positive multiple of 3";
    if (mesh.normals.size() != mesh.positions.size())
      return where + "normal count differs from position count";
    for (std::uint32_t index : mesh.indices)
      if (index >= mesh.positions.size())
        return where + "index " + std::to_string(index) + " out of range (" +
               std::to_string(mesh.positions.size()) + " vertices)";
    for (const glm::vec3& p : mesh.positions)
      if (!finite(p)) return where + "non-finite vertex position";
    for (const glm::vec3& n : mesh.normals)
      if (!finite(n)) return where + "non-finite normal";
  }
  const AreaLight& light = scene.light;
  if (!finite(light.center) || !finite(light.forward) || !finite(light.up))
    return "light: non-finite center, forward or up";
  if (!(light.width > 0 && light.height > 0) || !std::isfinite(light.width) ||
      !std::isfinite(light.height))
    return "light: width and height must be positive and finite";
  if (glm::length(light.forward) < 1e-6f || glm::length(light.up) < 1e-6f ||
      glm::length(glm::cross(light.forward, light.up)) < 1e-3f * glm::length(light.forward) *
                                                              glm::length(light.up))
    return "light: forward and up must be non-zero and not parallel";
  const Camera& camera = scene.camera;
  if (!finite(camera.position) || !finite(camera.target) || !finite(camera.up) ||
      glm::length(camera.target - camera.position) < 1e-6f)
    return "camera: position and target must be finite and distinct";
  if (!(camera.fovYDegrees > 1 && camera.fovYDegrees < 179))
    return "camera: fovY must be in (1, 179) degrees";
  return "";
}

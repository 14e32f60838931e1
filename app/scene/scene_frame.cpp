#include "scene/scene_frame.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "scene/mesh_builders.h"

namespace {

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

std::string withThousands(size_t value) {
  std::string digits = std::to_string(value), result;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) result += ',';
    result += digits[i];
  }
  return result;
}

bool inside(const Bounds& b, const glm::vec3& p) {
  return p.x > b.min.x && p.y > b.min.y && p.z > b.min.z && p.x < b.max.x && p.y < b.max.y &&
         p.z < b.max.z;
}

}  // namespace

Bounds framedBounds(const Scene& scene) {
  Bounds bounds = scene.bounds(true);
  return bounds.empty() ? scene.bounds(false) : bounds;
}

void frameScene(Scene& scene) {
  const Bounds bounds = framedBounds(scene);
  if (bounds.empty()) return;
  const glm::vec3 center = 0.5f * (bounds.min + bounds.max);
  const glm::vec3 extent = bounds.max - bounds.min;
  const float side = std::max({extent.x, extent.y, extent.z, 1e-6f});
  const float radius = std::max(0.5f * glm::length(extent), 1e-6f);

  // Camera: the bounding sphere's angular radius is 85 % of half the field of view.
  Camera& camera = scene.camera;
  const float halfFov = glm::radians(0.5f * camera.fovYDegrees);
  const float distance = radius / std::sin(0.85f * halfFov);
  const glm::vec3 from = glm::normalize(glm::vec3(0.35f, 0.55f, 1.0f));
  camera.target = center;
  camera.position = center + distance * from;
  camera.up = {0, 1, 0};

  // Ground: a square under the lowest point.
  const float groundSide = 5.0f * side;
  const glm::mat4 groundPlace =
      glm::scale(glm::translate(glm::mat4(1), {center.x, bounds.min.y, center.z}),
                 glm::vec3(groundSide));
  bool replaced = false, anyReceiver = false;
  for (SceneObject& object : scene.objects) {
    anyReceiver = anyReceiver || object.receiverOnly;
    if (object.receiverOnly && object.name == "ground") {
      object.mesh = makeQuad(1.0f, groundPlace);
      replaced = true;
    }
  }
  if (!replaced && !anyReceiver)
    scene.objects.push_back({"ground", makeQuad(1.0f, groundPlace), glm::vec3(0.85f), true});

  // Light: above the top by the largest side, slightly to one side so that the shadow falls
  // beside the model as well as under it, facing the model's centre.
  AreaLight& light = scene.light;
  light.center = {center.x + 0.2f * side, bounds.max.y + side, center.z + 0.2f * side};
  light.forward = glm::normalize(center - light.center);
  const glm::vec3 right = glm::normalize(glm::cross(light.forward, glm::vec3(0, 0, -1)));
  light.up = glm::normalize(glm::cross(right, light.forward));
  light.width = light.height = 0.5f * side;
}

std::string boundsText(const Bounds& b) {
  if (b.empty()) return "empty";
  const glm::vec3 e = b.max - b.min;
  return "x [" + number(b.min.x) + ", " + number(b.max.x) + "] y [" + number(b.min.y) + ", " +
         number(b.max.y) + "] z [" + number(b.min.z) + ", " + number(b.max.z) + "] (size " +
         number(e.x) + " x " + number(e.y) + " x " + number(e.z) + ")";
}

std::string sceneSummary(const Scene& scene) {
  std::string text = withThousands(scene.triangleCount()) + " triangles, " +
                     withThousands(scene.objects.size()) + " objects; bounds " +
                     boundsText(scene.bounds(false));
  for (const std::string& note : scene.notes) text += "; " + note;
  return text;
}

std::vector<std::string> cameraWarnings(const Scene& scene) {
  std::vector<std::string> warnings;
  const Bounds bounds = framedBounds(scene);
  if (bounds.empty()) return warnings;
  const Camera& camera = scene.camera;
  const char* fix = "; 'Frame scene' in the scene panel (script action frame_scene) fits the "
                    "camera, ground and light to the model";
  if (inside(bounds, camera.position)) {
    warnings.push_back("the camera at (" + number(camera.position.x) + ", " +
                       number(camera.position.y) + ", " + number(camera.position.z) +
                       ") is inside the model's bounds " + boundsText(bounds) + fix);
    return warnings;
  }
  const glm::vec3 center = 0.5f * (bounds.min + bounds.max);
  const glm::vec3 view = glm::normalize(camera.target - camera.position);
  const glm::vec3 toCenter = center - camera.position;
  const float along = glm::dot(toCenter, view);
  const float radius = 0.5f * glm::length(bounds.max - bounds.min);
  const float off = glm::length(toCenter - along * view);
  const float halfFov = glm::radians(0.5f * camera.fovYDegrees);
  // The whole bounding sphere outside the view cone (with a margin for wide images).
  if (along + radius < 0 || off - radius > 1.8f * std::tan(halfFov) * std::max(along, 0.0f))
    warnings.push_back("the camera does not look at the model (bounds " + boundsText(bounds) +
                       ")" + fix);
  return warnings;
}

#include "window/ui_camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace {
glm::vec3 rotate(glm::vec3 v, float angle, glm::vec3 axis) {
  return glm::vec3(glm::rotate(glm::mat4(1), angle, glm::normalize(axis)) * glm::vec4(v, 0));
}
}  // namespace

// 1. Rotate the offset from the target; refuse pitches that would flip over the pole.
void orbitCamera(Camera& camera, float yaw, float pitch) {
  const glm::vec3 up = glm::normalize(camera.up);
  glm::vec3 offset = camera.position - camera.target;
  offset = rotate(offset, yaw, up);
  const glm::vec3 right = glm::cross(up, offset);
  if (glm::length(right) > 1e-6f) {
    const glm::vec3 pitched = rotate(offset, pitch, right);
    const float cosine = glm::dot(glm::normalize(pitched), up);
    if (std::abs(cosine) < 0.995f) offset = pitched;
  }
  camera.position = camera.target + offset;
}

// 2. Move both points along the view's right and up vectors.
void panCamera(Camera& camera, float right, float up) {
  const glm::vec3 forward = camera.target - camera.position;
  const float distance = glm::length(forward);
  const glm::vec3 rightAxis = glm::normalize(glm::cross(forward, camera.up));
  const glm::vec3 upAxis = glm::normalize(glm::cross(rightAxis, forward));
  const glm::vec3 move = distance * (right * rightAxis + up * upAxis);
  camera.position += move;
  camera.target += move;
}

// 3. Scale the offset from the target.
void dollyCamera(Camera& camera, float factor) {
  const glm::vec3 offset = camera.position - camera.target;
  const float distance = glm::length(offset);
  const float next = std::clamp(distance * factor, 0.05f, 1000.0f);
  camera.position = camera.target + offset * (next / distance);
}

// 4. forward = (cos p sin y, sin p, -cos p cos y): yaw 0 looks along -z.
void lightAngles(const AreaLight& light, float& yawDegrees, float& pitchDegrees) {
  const glm::vec3 f = glm::normalize(light.forward);
  pitchDegrees = glm::degrees(std::asin(std::clamp(f.y, -1.0f, 1.0f)));
  yawDegrees = std::abs(f.x) + std::abs(f.z) < 1e-6f ? 0.0f : glm::degrees(std::atan2(f.x, -f.z));
}

void setLightAngles(AreaLight& light, float yawDegrees, float pitchDegrees) {
  const float yaw = glm::radians(yawDegrees), pitch = glm::radians(pitchDegrees);
  light.forward = glm::normalize(glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                                           -std::cos(pitch) * std::cos(yaw)));
  // Keep `up` as close as possible to the old one (Gram-Schmidt), else any perpendicular.
  glm::vec3 up = light.up - glm::dot(light.up, light.forward) * light.forward;
  if (glm::length(up) < 1e-4f) {
    const glm::vec3 any = std::abs(light.forward.z) < 0.9f ? glm::vec3(0, 0, -1) : glm::vec3(1, 0, 0);
    up = any - glm::dot(any, light.forward) * light.forward;
  }
  light.up = glm::normalize(up);
}

#include "scene/light_frame.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

float lightDepthEq31(float size, float fovRadians) {
  return size / (2.0f * std::tan(fovRadians / 2.0f));
}

LightFrame computeLightFrame(const AreaLight& light, const Bounds& sceneBounds,
                             float fovDegrees) {
  LightFrame frame{};
  frame.forward = glm::normalize(light.forward);
  frame.right = glm::normalize(glm::cross(frame.forward, light.up));
  frame.up = glm::cross(frame.right, frame.forward);

  const float longest = std::max(light.width, light.height);
  frame.lightDepth = lightDepthEq31(longest, glm::radians(fovDegrees));
  frame.tanHalfFovX = 0.5f * light.width / frame.lightDepth;
  frame.tanHalfFovY = 0.5f * light.height / frame.lightDepth;
  frame.wsProjectionPoint = light.center - frame.forward * frame.lightDepth;

  // Far plane: the deepest scene point along the axis, with a margin; never closer than
  // twice the near plane so the range is never degenerate.
  float deepest = 2.0f * frame.lightDepth;
  if (!sceneBounds.empty())
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 p{corner & 1 ? sceneBounds.max.x : sceneBounds.min.x,
                        corner & 2 ? sceneBounds.max.y : sceneBounds.min.y,
                        corner & 4 ? sceneBounds.max.z : sceneBounds.min.z};
      deepest = std::max(deepest, glm::dot(p - frame.wsProjectionPoint, frame.forward));
    }
  frame.zNear = frame.lightDepth;
  frame.zFar = deepest * 1.01f + 1e-3f;

  frame.lightViewFromWorld = glm::lookAt(frame.wsProjectionPoint,
                                         frame.wsProjectionPoint + frame.forward, frame.up);
  // Off-axis-free perspective with independent x and y half-angles.
  glm::mat4 projection(0.0f);
  projection[0][0] = 1.0f / frame.tanHalfFovX;
  projection[1][1] = 1.0f / frame.tanHalfFovY;
  projection[2][2] = -(frame.zFar + frame.zNear) / (frame.zFar - frame.zNear);
  projection[2][3] = -1.0f;
  projection[3][2] = -2.0f * frame.zFar * frame.zNear / (frame.zFar - frame.zNear);
  frame.lightClipFromWorld = projection * frame.lightViewFromWorld;
  return frame;
}

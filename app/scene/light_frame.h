// The light's projection (thesis §3, Eq 3.1): a perspective frustum from a projection point
// behind the light's center whose cross-section at the near plane is the light rectangle.
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"

struct LightFrame {
  float lightDepth;         // Eq 3.1: distance from the projection point to the light plane
  glm::vec3 wsProjectionPoint;
  float zNear, zFar;        // linear depth range along the light axis (zNear = lightDepth)
  float tanHalfFovX, tanHalfFovY;
  glm::mat4 lightViewFromWorld;
  glm::mat4 lightClipFromWorld;
  glm::vec3 right, up, forward;  // orthonormal light frame
  int mapSize = 0;  // texels per side of the light maps (set by the `light` stage)
  int layers = 2;   // depth layers modelling the occluders, 1-3 (set by the `light` stage)
  int hashKind = 0; // HASH_* of the light samples (shared/hash_kinds.h; set by the `light` stage)
};

// Eq 3.1 for a square light of side `size`: light depth = size / (2 tan(fov / 2)).
float lightDepthEq31(float size, float fovRadians);

// For a rectangle, fov applies to the longer side; the shorter side's fov follows so the
// rectangle fills the near plane exactly. zFar reaches past every occluder and receiver.
LightFrame computeLightFrame(const AreaLight& light, const Bounds& sceneBounds,
                             float fovDegrees);

// Mouse control of the scene camera (orbit, pan, dolly about its target) and of the light's
// orientation. The pipeline recomputes every matrix from Scene::camera / Scene::light each
// run, so these functions only move points and directions.
#pragma once
#include "scene/scene.h"

// 1. Orbit: yaw about the camera's up axis and pitch about its right axis (radians), keeping
//    the distance to the target; pitch stops short of the poles so `up` stays valid.
void orbitCamera(Camera& camera, float yaw, float pitch);
// 2. Pan: moves position and target together in the view plane; `right`, `up` are fractions
//    of the distance to the target (a drag across the view moves about one view width).
void panCamera(Camera& camera, float right, float up);
// 3. Dolly: distance to the target times `factor` (clamped to stay in front of the target).
void dollyCamera(Camera& camera, float factor);

// 4. Light orientation as yaw / pitch of its forward direction (degrees; pitch -90 = down),
//    and back; `up` is re-orthogonalised so the light's frame stays orthonormal.
void lightAngles(const AreaLight& light, float& yawDegrees, float& pitchDegrees);
void setLightAngles(AreaLight& light, float yawDegrees, float pitchDegrees);

// The eye's near and far planes from what the camera sees (docs/accuracy.md): the range of view
// depths of the scene's triangles clipped to the camera's view pyramid. A fixed fraction of
// the scene's size (as before) put the near plane 7 units out when a 5000-unit ground
// entered the scene, and a close camera then drew nothing.
#pragma once
#include "scene/scene.h"

struct EyeDepthRange {
  float eyeNear = 0.1f, eyeFar = 100.0f;
  bool seesGeometry = false;  // false: no triangle lies inside the view pyramid
};

// Clips every triangle to the view pyramid (the four side planes, and in front of the eye),
// takes the smallest and largest view depth (distance along the view axis) of what is
// left, and widens them by a small margin: near = 0.9 x smallest (at least 1e-5 x far, so
// the depth buffer keeps its precision), far = 1.1 x largest. With nothing in view:
// near/far around the target's distance, and seesGeometry = false.
EyeDepthRange eyeDepthRange(const Scene& scene, float aspect);

// The same, and a loud warning on stderr when the camera sees nothing (once until it sees
// something again, not every frame).
EyeDepthRange eyeDepthRangeOrWarn(const Scene& scene, float aspect);

// Fitting the camera, the ground and the light to a model of any size, and saying how big a
// loaded scene is (a researcher's model comes in its own units: a scan in millimetres spans
// hundreds of units, a CAD part in metres a fraction of one).
#pragma once
#include <string>
#include <vector>

#include "scene/scene.h"

// The bounds the framing fits: the occluders (objects that are not receiver-only), or every
// object when there are none.
Bounds framedBounds(const Scene& scene);

// Places the camera, the ground and the light around the occluders, in the scene's units:
// - camera: looks at the centre of the bounds from the front and above, far enough that the
//   bounding sphere fills about 85 % of the vertical field of view (so it is outside it);
// - ground: the receiver-only object named "ground" becomes a square five times the model's
//   largest side under its lowest point (one is added when the scene has no receiver);
// - light: above the model by its largest side, aimed at its centre, half as wide as it.
// Objects other than the ground are not moved.
void frameScene(Scene& scene);

// "91,216 triangles, 3 objects; bounds x [-1.2, 1.2] y [0, 2.5] z [-0.6, 0.6] (size 2.4 x
// 2.5 x 1.2)", plus what loading did (Scene::notes), for stderr, run.json and the scene panel.
std::string sceneSummary(const Scene& scene);
std::string boundsText(const Bounds& bounds);

// Warnings for a camera that cannot see the model: inside the occluders' bounds, or looking
// away from them. Empty when it sees them.
std::vector<std::string> cameraWarnings(const Scene& scene);

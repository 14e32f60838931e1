// `auto` field of view of the light's frustum (light.fov_degrees=auto, the default;
// docs/decisions/135-light-frustum-fitted-to-the-casters.md).
//
// Thesis §3, Eq 3.1: the frustum's apex sits lightDepth = side / (2 tan(fov / 2)) behind the
// light's centre, so its cross-section at the light plane is the light rectangle. A receiver
// inside the frustum is handled by every depth-map method: the segment from it to any light
// point lies inside too (the frustum is convex and holds the light). A receiver outside is
// lit (decision 009), which is wrong where a caster shadows it.
//
// The rule, for every point of the light at once: in light coordinates (x along the light's
// width w, y along its height h, z the distance in front of the light plane) a caster point c
// shadows points c + s (c - L), s >= 0, for every light point L. The frustum's side x = w/2
// + z t (t = tan of its half-angle across the width) contains all of them, for every s and
// every L, exactly when t >= (|c.x| + w/2) / c.z: the direction from the light's far edge
// through c. So with t_x = max over the casters' vertices of (|x| + w/2) / z (and t_y with h)
// the whole shadow of every caster lies inside the maps, whatever the receivers are (a
// triangle's maximum of this quotient is at a vertex: it is linear-fractional on either side
// of x = 0). The frustum keeps Eq 3.1's shape: lightDepth = min(w / (2 t_x), h / (2 t_y)), the
// fov that of the longer side.
//
// `auto` takes the default 90 degrees unless the casters need more (never narrower: see the
// decision), at most `maxDegrees`. Casters it cannot cover are named: vertices at or behind
// the light plane (a caster that reaches through it: its part next to the plane casts a
// shadow no frustum holds), or vertices that would need more than `maxDegrees`.
#pragma once
#include <string>
#include <vector>

#include "scene/scene.h"

inline constexpr double kAutoFovFloorDegrees = 90.0;

struct FrustumFit {
  double fovDegrees = kAutoFovFloorDegrees;  // what `auto` takes
  double neededDegrees = 0;   // what the coverable casters need (0: no caster in front)
  double neededTanX = 0, neededTanY = 0;  // t_x, t_y above
  std::vector<std::string> uncovered;  // casters (object names) not wholly covered
  std::string reason;   // one sentence for Frame::autoReasons
  std::string warning;  // "" or a sentence naming the uncovered casters
};

// For `scene`'s casters (objects not receiver_only) and light, on the CPU (every vertex once).
FrustumFit fitLightFrustum(const Scene& scene, double maxDegrees);

// The warning for a fixed field of view (light.fov_degrees set by hand): "" when it covers
// every coverable caster.
std::string fixedFovWarning(const FrustumFit& fit, double fixedDegrees);

// Up to six names, quoted, for a warning: 'a', 'b' and 3 more.
std::string quotedNames(const std::vector<std::string>& list);

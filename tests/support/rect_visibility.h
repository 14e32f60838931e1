// Exact visibility of a rectangular light through rectangles parallel to it
// (docs/design.md#tests), in world space and double precision, written without the shaders'
// light-space conventions: the oracle of the soft-shadow-map tests (tests/stages/test_ssm*.cpp).
//
// Seen from a receiver point R, a rectangle parallel to the light projects (back-projects)
// onto the light plane as a rectangle with the same axes; the hidden fraction of the light
// is the area of its intersection with the light rectangle over the light's area, a
// product of two 1D interval overlaps.
#pragma once
#include <glm/glm.hpp>

struct RectLight {
  glm::dvec3 center, right, up, forward;  // orthonormal; forward = direction it emits to
  double halfWidth, halfHeight;           // along right, up
};

// A rectangle parallel to the light, sides along the light's right and up.
struct ParallelRect {
  glm::dvec3 center;
  double halfWidth, halfHeight;
};

// A rectangle in light coordinates normalized so that the light is [0,1]^2.
struct LightRect {
  double x0, x1, y0, y1;
  bool empty;  // nothing hidden: the rectangle is not between the light and the receiver
};

// Length of [a0, a1] ∩ [b0, b1] (0 when disjoint).
double intervalOverlap(double a0, double a1, double b0, double b1);

// The back-projection of `rect` from `wsReceiver` onto the light plane, unclipped.
LightRect backProject(const RectLight& light, const ParallelRect& rect, const glm::dvec3& wsReceiver);

// Fraction of the light's area that `rect` hides from `wsReceiver`, in [0, 1].
double hiddenFraction(const RectLight& light, const ParallelRect& rect, const glm::dvec3& wsReceiver);

// Fraction hidden by the union of two parallel rectangles: |A| + |B| - |A ∩ B| on the light.
double hiddenFractionOfUnion(const RectLight& light, const ParallelRect& a, const ParallelRect& b,
                             const glm::dvec3& wsReceiver);

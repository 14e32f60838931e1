#include "rect_visibility.h"

#include <algorithm>

double intervalOverlap(double a0, double a1, double b0, double b1) {
  return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}

namespace {

// Where the line from `from` through `through` meets the light plane, in [0,1]^2 light units.
glm::dvec2 onLightPlane(const RectLight& light, const glm::dvec3& from, const glm::dvec3& through) {
  const double t = glm::dot(light.center - from, light.forward) /
                   glm::dot(through - from, light.forward);
  const glm::dvec3 hit = from + t * (through - from) - light.center;
  return {(glm::dot(hit, light.right) + light.halfWidth) / (2 * light.halfWidth),
          (glm::dot(hit, light.up) + light.halfHeight) / (2 * light.halfHeight)};
}

double clippedArea(const LightRect& r) {
  if (r.empty) return 0;
  return intervalOverlap(r.x0, r.x1, 0, 1) * intervalOverlap(r.y0, r.y1, 0, 1);
}

}  // namespace

LightRect backProject(const RectLight& light, const ParallelRect& rect, const glm::dvec3& wsReceiver) {
  const double receiverDepth = glm::dot(wsReceiver - light.center, light.forward);
  const double rectDepth = glm::dot(rect.center - light.center, light.forward);
  if (!(rectDepth > 0 && rectDepth < receiverDepth)) return {0, 0, 0, 0, true};
  const glm::dvec3 lowCorner = rect.center - rect.halfWidth * light.right - rect.halfHeight * light.up;
  const glm::dvec3 highCorner = rect.center + rect.halfWidth * light.right + rect.halfHeight * light.up;
  const glm::dvec2 a = onLightPlane(light, wsReceiver, lowCorner);
  const glm::dvec2 b = onLightPlane(light, wsReceiver, highCorner);
  return {std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y), false};
}

double hiddenFraction(const RectLight& light, const ParallelRect& rect, const glm::dvec3& wsReceiver) {
  return clippedArea(backProject(light, rect, wsReceiver));
}

double hiddenFractionOfUnion(const RectLight& light, const ParallelRect& a, const ParallelRect& b,
                             const glm::dvec3& wsReceiver) {
  const LightRect ra = backProject(light, a, wsReceiver), rb = backProject(light, b, wsReceiver);
  double both = 0;
  if (!ra.empty && !rb.empty) {
    const LightRect meet{std::max(ra.x0, rb.x0), std::min(ra.x1, rb.x1),
                         std::max(ra.y0, rb.y0), std::min(ra.y1, rb.y1), false};
    if (meet.x0 < meet.x1 && meet.y0 < meet.y1) both = clippedArea(meet);
  }
  return clippedArea(ra) + clippedArea(rb) - both;
}

#include "shared_inputs/light/occluder_image.h"

#include "shared_inputs/weighted_percentile.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

double cross(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Akl-Toussaint: the points extreme along x, y, x + y and x - y bound an octagon inside the
// hull; a point strictly inside it is no hull vertex. On a mesh's projection that removes
// nearly every point in one pass before the sort (the dragon's ~440k vertices).
void dropInteriorPoints(std::vector<glm::dvec2>& points) {
  if (points.size() < 64) return;
  const glm::dvec2 directions[4] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
  glm::dvec2 extreme[8];
  for (int d = 0; d < 4; ++d) {
    size_t low = 0, high = 0;
    for (size_t i = 1; i < points.size(); ++i) {
      const double s = glm::dot(points[i], directions[d]);
      if (s < glm::dot(points[low], directions[d])) low = i;
      if (s > glm::dot(points[high], directions[d])) high = i;
    }
    extreme[2 * d] = points[low];
    extreme[2 * d + 1] = points[high];
  }
  // The octagon in counter-clockwise order: min y, max (x - y), max x, max (x + y), max y,
  // min (x - y), min x, min (x + y).
  const glm::dvec2 octagon[8] = {extreme[2], extreme[7], extreme[1], extreme[5],
                                 extreme[3], extreme[6], extreme[0], extreme[4]};
  const auto strictlyInside = [&](const glm::dvec2& p) {
    bool anyEdge = false;
    for (int e = 0; e < 8; ++e) {
      const glm::dvec2 &a = octagon[e], &b = octagon[(e + 1) % 8];
      if (a == b) continue;  // a repeated extreme point
      anyEdge = true;
      if (cross(a, b, p) <= 0) return false;
    }
    return anyEdge;
  };
  points.erase(std::remove_if(points.begin(), points.end(), strictlyInside), points.end());
}

}  // namespace

double convexHullMinimumWidth(std::vector<glm::dvec2> points) {
  dropInteriorPoints(points);
  // 1. The hull, counter-clockwise (Andrew's monotone chain).
  std::sort(points.begin(), points.end(), [](const glm::dvec2& a, const glm::dvec2& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return 0;
  std::vector<glm::dvec2> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) {  // lower chain
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {  // upper chain
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);  // the last point is the first
  const size_t n = hull.size();
  if (n < 3) return 0;  // every point on one line
  // 2. The minimum width lies across one of the hull's edges (rotating calipers): for each
  //    edge, the farthest vertex from its line; that vertex only moves forward as the edge
  //    turns.
  double width = std::numeric_limits<double>::infinity();
  size_t far = 1;
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec2 &a = hull[i], &b = hull[(i + 1) % n];
    while (cross(a, b, hull[(far + 1) % n]) > cross(a, b, hull[far])) far = (far + 1) % n;
    width = std::min(width, cross(a, b, hull[far]) / glm::length(b - a));
  }
  return width;
}

std::vector<OccluderImage> occluderImages(const Scene& scene, const LightFrame& light) {
  std::vector<OccluderImage> images(scene.objects.size());
  const double tanHalfFov = std::max(light.tanHalfFovX, light.tanHalfFovY);
  std::vector<glm::dvec2> image;
  for (size_t o = 0; o < scene.objects.size(); ++o) {
    const SceneObject& object = scene.objects[o];
    if (object.receiverOnly || object.mesh.positions.empty()) continue;
    image.clear();
    double zMin = std::numeric_limits<double>::infinity(), zMax = 0;
    bool bounded = true;
    for (const glm::vec3& p : object.mesh.positions) {
      // Through the projection point onto the plane at unit depth (the tangents of the
      // light's frustum: the map spans [-tan(fov/2), tan(fov/2)] on it).
      const glm::dvec3 fromProjection = glm::dvec3(p) - glm::dvec3(light.wsProjectionPoint);
      const double z = glm::dot(fromProjection, glm::dvec3(light.forward));
      if (!(z > 1e-9)) {
        bounded = false;
        break;
      }
      image.emplace_back(glm::dot(fromProjection, glm::dvec3(light.right)) / z,
                         glm::dot(fromProjection, glm::dvec3(light.up)) / z);
      zMin = std::min(zMin, z);
      zMax = std::max(zMax, z);
    }
    if (!bounded) continue;
    const double width = convexHullMinimumWidth(image);
    // The map's texels are 2 tan(fov/2) / size wide on that plane along its wider side.
    images[o].width = width / (2.0 * tanHalfFov);
    const double worldWidth = width * zMin;  // the image's width at the object's nearest depth
    images[o].depthOverWidth = worldWidth > 0 ? (zMax - zMin) / worldWidth
                                              : std::numeric_limits<double>::infinity();
  }
  return images;
}

SteepOccluders steepOccluders(const Scene& scene, const LightFrame& light,
                              const std::vector<unsigned>& probeObjects,
                              const std::vector<double>& probeAreas, double steepDepthOverWidth,
                              int largestMap) {
  const std::vector<OccluderImage> images = occluderImages(scene, light);
  SteepOccluders out;
  std::vector<double> widths;
  std::vector<bool> named(scene.objects.size(), false);
  for (unsigned o : probeObjects) {
    const OccluderImage& image = images[o];
    const bool steep = image.depthOverWidth >= steepDepthOverWidth;
    const bool inNoMap = steep && image.width * double(largestMap) < 1.0;
    widths.push_back(steep && !inNoMap ? image.width : std::numeric_limits<double>::infinity());
    if (inNoMap && !named[o]) {
      named[o] = true;
      out.inNoMap.push_back(scene.objects[o].name);
    }
  }
  if (!widths.empty()) out.narrowestImage = weightedPercentile(widths, probeAreas, 0.02);
  return out;
}

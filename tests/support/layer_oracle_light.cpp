// Light-space side of the layer oracle: world <-> map coordinates, rays from light samples to
// receivers (thesis §3: ray from a point on the light to the fragment, shortened by a bias),
// the third layer (§3.4) and dense visibility. See layer_oracle.h.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "support/layer_oracle.h"

glm::dvec3 lightMapFromWorld(const LightFrame& frame, int mapW, int mapH, const glm::dvec3& ws) {
  const glm::dvec4 view = glm::dmat4(frame.lightViewFromWorld) * glm::dvec4(ws, 1.0);
  const double z = -view.z;  // the view looks down -z; z is the distance along the light axis
  const glm::dvec2 ndc(view.x / (z * double(frame.tanHalfFovX)),
                       view.y / (z * double(frame.tanHalfFovY)));
  const glm::dvec2 texel = (ndc * 0.5 + 0.5) * glm::dvec2(mapW, mapH);
  return {texel, z};
}

glm::dvec3 worldFromLightMap(const LightFrame& frame, int mapW, int mapH, glm::dvec2 texel,
                             double z) {
  const glm::dvec2 ndc = texel / glm::dvec2(mapW, mapH) * 2.0 - 1.0;
  const glm::dvec4 view(ndc.x * z * double(frame.tanHalfFovX), ndc.y * z * double(frame.tanHalfFovY),
                        -z, 1.0);
  return glm::dvec3(glm::inverse(glm::dmat4(frame.lightViewFromWorld)) * view);
}

glm::dvec3 lightSampleWorld(const LightFrame& frame, const AreaLight& light, glm::vec2 sample01) {
  return glm::dvec3(light.center) +
         (2.0 * sample01.x - 1.0) * glm::dvec3(frame.right) * (0.5 * light.width) +
         (2.0 * sample01.y - 1.0) * glm::dvec3(frame.up) * (0.5 * light.height);
}

OracleRay makeRay(const LightFrame& frame, const AreaLight& light, int mapW, int mapH,
                  glm::vec2 sample01, const glm::vec3& wsReceiver, float biasWorld) {
  OracleRay ray;
  // The light rectangle is the frustum's cross-section at the near plane (Eq 3.1), so the
  // sample's map position is the sample itself; no projection round trip.
  ray.texelA = sample01 * glm::vec2(mapW, mapH);
  ray.zA = frame.zNear;
  const glm::dvec3 wsLight = lightSampleWorld(frame, light, sample01);
  const glm::dvec3 toLight = wsLight - glm::dvec3(wsReceiver);
  const double distance = glm::length(toLight);
  if (distance <= double(biasWorld)) {  // the bias eats the whole ray: it ends at the light
    ray.texelB = ray.texelA;
    ray.zB = ray.zA;
    return ray;
  }
  const glm::dvec3 wsEnd = glm::dvec3(wsReceiver) + toLight * (std::max(0.0, double(biasWorld)) / distance);
  const glm::dvec3 map = lightMapFromWorld(frame, mapW, mapH, wsEnd);
  ray.texelB = glm::vec2(map.x, map.y);
  ray.zB = float(map.z);
  return ray;
}

OracleHit traceThreeLayers(const LayerMaps& maps, const OracleRay& ray, const LightFrame& frame,
                           const EyeVisibility& visibleFromEye, int interiorSamples) {
  const RayDepth depth(ray, frame.zNear, frame.zFar);
  OracleHit hit;
  hit.texelsOnRay = int(texelSpans(ray, {0, 0}, {maps.width, maps.height}).size());
  hit.texelsVisited = hit.texelsOnRay;
  for (const OccludedPiece& piece : occludedPieces(maps, ray, frame.zNear, frame.zFar)) {
    // Samples of the part of the ray inside [near, far]: its ends and interior points.
    const int last = piece.s1 > piece.s0 ? interiorSamples + 1 : 0;
    for (int k = 0; k <= last; ++k) {
      const double s = k == last ? piece.s1 : piece.s0 + (piece.s1 - piece.s0) * k / (interiorSamples + 1);
      const glm::dvec3 ws =
          worldFromLightMap(frame, maps.width, maps.height, rayPoint(ray, s), depth.zAt(s));
      if (visibleFromEye(ws)) continue;  // §3.4: the eye sees this point, so it is empty space
      hit.occluded = true;
      hit.s = hit.sFirstHitEnd = s;
      hit.texel = piece.texel;
      hit.texelsVisited = piece.spanIndex + 1;
      hit.clearance = 0;
      return hit;  // sampled: hitLength stays 0
    }
  }
  return hit;  // clearance is not measured for three layers
}

float denseVisibility(const LightFrame& frame, const AreaLight& light, int mapW, int mapH,
                      const glm::vec3& wsReceiver, float biasWorld, int n,
                      const std::function<OracleHit(const OracleRay&)>& trace) {
  int clear = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const glm::vec2 sample((i + 0.5f) / n, (j + 0.5f) / n);
      clear += !trace(makeRay(frame, light, mapW, mapH, sample, wsReceiver, biasWorld)).occluded;
    }
  return float(clear) / float(n * n);
}

float denseVisibility(const LayerMaps& maps, const LightFrame& frame, const AreaLight& light,
                      const glm::vec3& wsReceiver, float biasWorld, int n, int layers) {
  if (layers != 1 && layers != 2) throw std::invalid_argument("denseVisibility: layers is 1 or 2");
  return denseVisibility(frame, light, maps.width, maps.height, wsReceiver, biasWorld, n,
                         [&](const OracleRay& ray) {
                           return layers == 1 ? traceOneLayer(maps, ray, frame.zNear, frame.zFar)
                                              : traceTwoLayers(maps, ray, frame.zNear, frame.zFar);
                         });
}

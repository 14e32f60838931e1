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
  const std::vector<TexelSpan> spans = texelSpans(ray, {0, 0}, {maps.width, maps.height});
  OracleHit hit;
  hit.texelsOnRay = int(spans.size());
  std::vector<double> samples;
  for (const TexelSpan& span : spans) {
    if (!hit.occluded) ++hit.texelsVisited;
    const double lo = maps.nearAt(span.texel), hi = maps.farAt(span.texel);
    if (lo > hi || hit.occluded) continue;
    // Owned ends plus evenly spaced interior points (a point span is its one point).
    samples.clear();
    if (span.owns0) samples.push_back(span.s0);
    for (int k = 1; k <= interiorSamples && span.s1 > span.s0; ++k)
      samples.push_back(span.s0 + (span.s1 - span.s0) * k / (interiorSamples + 1));
    if (span.owns1 && span.s1 > span.s0) samples.push_back(span.s1);
    for (double s : samples) {
      const double d = depth.at(s);
      if (d < lo || d > hi) continue;
      const glm::dvec3 ws =
          worldFromLightMap(frame, maps.width, maps.height, rayPoint(ray, s), depth.zAt(s));
      if (visibleFromEye(ws)) continue;  // §3.4: seen by the eye, so empty space
      hit.occluded = true;
      hit.s = hit.sFirstHitEnd = s;
      hit.texel = span.texel;
      hit.clearance = 0;
      break;
    }
  }
  return hit;  // sampled: hitLength stays 0, clearance is not measured
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

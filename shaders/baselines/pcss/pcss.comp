// Stage `pcss`: Percentage-Closer Soft Shadows (Fernando 2005) on the near layer, in steps:
//   1. blocker search region: the light's cone from the receiver, cut by the plane of the
//      nearest occluder in the map (no texel outside it can hold a blocker);
//   2. average blocker depth over the taps in that region that are nearer than the receiver;
//   3. penumbra width by similar triangles, w = W (zR - zAvg) / (zAvg - zLight), i.e. the
//      light's cone cut at the average blocker plane: the filter region;
//   4. percentage-closer filtering over the filter region.
// Depths: the map stores linear light depth (light_block.h); blockers are averaged as
// distances along the light axis and the triangles measured from the light plane (Eq 3.1),
// not from the projection point: one depth space throughout.
// Blockers (steps 2 and 4) are texels whose surface point lies in front of the receiver's
// tangent plane (receiver-plane depth bias): a tap compared with the receiver's own depth
// finds the receiver's surface itself in front wherever that surface slopes away from the
// light, and the region then collapses onto the receiver's texel (acne, self-shadow noise).
#include "shared/screen_pass.glsl"
#include "shared/bias.glsl"
#include "shared/hash.glsl"
#include "stages/baselines/pcss/pcss_layout.h"
#include "shared/ssm_layout.h"
layout(std140, binding = PCSS_PARAMS_BINDING) uniform PcssBlock { PcssParams pcss; };
// The near layer's depth bounds (depth_bounds.comp, run just before on the same layer).
layout(std430, binding = DEPTH_BOUNDS_BINDING) readonly buffer Bounds { DepthBounds nearBounds; };
layout(std430, binding = PCSS_TAPS_BINDING) readonly buffer Taps { vec2 taps[]; };
layout(binding = PCSS_WS_POSITION_UNIT) uniform sampler2D wsPositionImage;
layout(binding = PCSS_WS_NORMAL_UNIT) uniform sampler2D wsNormalImage;
layout(binding = PCSS_NEAR_UNIT) uniform sampler2D nearLayer;
layout(binding = PCSS_VISIBILITY_IMAGE, r32f) uniform writeonly image2D visibilityImage;
layout(binding = PCSS_SEARCH_RADIUS_IMAGE, r32f) uniform writeonly image2D searchRadiusImage;  // texels
layout(binding = PCSS_BLOCKER_DEPTH_IMAGE, r32f) uniform writeonly image2D blockerDepthImage;  // lsDepth, 0: none
layout(binding = PCSS_FILTER_RADIUS_IMAGE, r32f) uniform writeonly image2D filterRadiusImage;  // texels

// The light's cone from a receiver at (uvReceiver, zReceiver), cut by the plane at depth
// zCut: a square in map uv, returned as (centre, half-width). The light fills the map at its
// own plane (Eq 3.1), so its size in world units enters through the frustum, not through a
// constant; the cone's axis runs to the light centre (uv 0.5), not along the receiver's map
// ray, so the cut is off-centre (a centred region misses blockers on the side towards the
// light centre).
vec3 coneCut(vec2 uvReceiver, float zReceiver, float zCut) {
  float zLight = light.lightDepthRange.x;
  float towardsReceiver = zReceiver * (zCut - zLight) / ((zReceiver - zLight) * zCut);
  float halfWidth = 0.5 * zLight * (zReceiver - zCut) / ((zReceiver - zLight) * zCut);
  return vec3(0.5 + (uvReceiver - 0.5) * towardsReceiver, halfWidth);
}

// Tap i of the pattern, optionally shifted per pixel on the torus (a Cranley-Patterson
// rotation, which keeps the taps in the square region).
vec2 tap(int i, vec2 shift) {
  return fract(taps[i] * 0.5 + 0.5 + shift) * 2.0 - 1.0;
}

// The world point a map texel holds: the ray from the projection point through the texel's
// centre, at distance z along the light axis.
vec3 wsPointOfTexel(ivec2 texel, float z) {
  vec2 ndc = (vec2(texel) + 0.5) / vec2(light.mapSize.xy) * 2.0 - 1.0;
  vec3 wsProjection = light.wsLightCenter.xyz - light.wsLightForward.w * light.wsLightForward.xyz;
  return wsProjection + z * (light.wsLightForward.xyz + ndc.x * light.lightDepthRange.z * light.wsLightRight.xyz
                             + ndc.y * light.lightDepthRange.w * light.wsLightUp.xyz);
}

// The receiver as blockers see it: the biased point (moved towards the light, as every
// shadow-map test does) and its tangent plane, if it faces the light centre.
struct Receiver { float lsDepth; vec3 wsPoint; vec3 wsNormal; bool plane; };

// A tap's texel blocks the receiver if it is nearer the light and, for a receiver facing the
// light, in front of its tangent plane through the biased point.
bool blocks(Receiver receiver, ivec2 texel, float lsDepth) {
  if (lsDepth >= receiver.lsDepth) return false;
  if (!receiver.plane) return true;
  return dot(receiver.wsNormal, wsPointOfTexel(texel, lsDepthToZ(lsDepth)) - receiver.wsPoint) > 0.0;
}

void main() {
  ivec2 pixel = screenPixel();
  if (pixel.x < 0) return;
  vec4 wsPosition = texelFetch(wsPositionImage, pixel, 0);
  vec3 map = lightMapCoords(wsPosition.xyz);
  bool insideMap = all(greaterThanEqual(map.xy, vec2(0.0))) && all(lessThan(map.xy, vec2(1.0)))
                   && map.z > light.lightDepthRange.x;
  float visibility = 1.0, searchHalf = 0.0, blockerDepth = 0.0, filterHalf = 0.0;
  if (wsPosition.w > 0.0 && insideMap) {
    vec2 size = vec2(light.mapSize.xy);
    vec3 wsNormal = texelFetch(wsNormalImage, pixel, 0).xyz;
    vec3 wsToLight = normalize(light.wsLightCenter.xyz - wsPosition.xyz);
    float bias = light.bias.x;  // the light's Eq 3.2 group, as every shadow-map test
    if (light.bias.y != 0.0)
      bias += adaptiveBias(map.z, wsNormal, -light.wsLightForward.xyz, light.bias.z);
    // A receiver turned away from the light centre keeps the plain depth comparison.
    Receiver receiver = Receiver(zToLsDepth(map.z - bias),
                                 wsPosition.xyz - bias * light.wsLightForward.xyz, wsNormal,
                                 dot(wsNormal, wsToLight) > 0.0);
    vec2 shift = vec2(0.0);
    if (pcss.taps.z != 0)
      shift = toUnitSquare(hashRand(uvec4(pixel, 0u, 0u), frame.keys.x, int(light.sampling.x)).xy);

    // Step 1: the search region, the cone cut at the nearest occluder. It holds the cuts at
    // every depth between that occluder and the receiver (they shrink towards the receiver's
    // own uv, which it contains), so no blocker lies outside it.
    // The nearest occluder's z (lsDepthToZ of the smallest depth; the far plane when the map
    // holds no surface). `precise`: the same rounding wherever it is computed.
    precise float zNearest = light.lightDepthRange.y;
    if (nearBounds.count != 0u)
      zNearest = light.lightDepthRange.x + uintBitsToFloat(nearBounds.minBits)
                 * (light.lightDepthRange.y - light.lightDepthRange.x);
    vec3 search = zNearest < map.z ? coneCut(map.xy, map.z, zNearest) : vec3(map.xy, 0.0);
    searchHalf = search.z;
    // Step 2: average blocker depth over the taps (taps off the map find nothing).
    float blockerSum = 0.0;
    int blockers = 0;
    for (int i = 0; i < pcss.taps.x && searchHalf > 0.0; ++i) {
      vec2 uv = search.xy + searchHalf * tap(i, shift);
      if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) continue;
      ivec2 texel = ivec2(uv * size);
      float lsDepth = texelFetch(nearLayer, texel, 0).r;
      if (blocks(receiver, texel, lsDepth)) blockerSum += lsDepthToZ(lsDepth), ++blockers;
    }
    if (blockers > 0) {
      float zAverage = blockerSum / float(blockers);
      blockerDepth = zToLsDepth(zAverage);
      // Step 3: the light's cone cut at the average blocker (similar triangles).
      vec3 region = coneCut(map.xy, map.z, zAverage);
      filterHalf = region.z;
      // Step 4: percentage-closer filtering; taps off the map count as lit.
      int lit = 0;
      for (int i = 0; i < pcss.taps.y; ++i) {
        vec2 uv = region.xy + filterHalf * tap(pcss.taps.x + i, shift);
        bool onMap = all(greaterThanEqual(uv, vec2(0.0))) && all(lessThan(uv, vec2(1.0)));
        ivec2 texel = ivec2(uv * size);
        if (!onMap || !blocks(receiver, texel, texelFetch(nearLayer, texel, 0).r)) ++lit;
      }
      visibility = float(lit) / float(pcss.taps.y);
    }
    searchHalf *= size.x;
    filterHalf *= size.x;
  }
  imageStore(visibilityImage, pixel, vec4(visibility));
  imageStore(searchRadiusImage, pixel, vec4(searchHalf));
  imageStore(blockerDepthImage, pixel, vec4(blockerDepth));
  imageStore(filterRadiusImage, pixel, vec4(filterHalf));
}

// Stage `filter` (thesis §3, Fig 3.2e): one direction of the separable depth-sensitive
// Gaussian. A sample's weight is the Gaussian weight divided by (1 + |depth difference|)
// ("inversely proportional to the difference between its depth and that of the central
// sample (plus 1 to prevent division by zero)"); the depth is the distance from the eye,
// scaled by uDepthScale. Optionally normal-sensitive ("a robust implementation would also
// include normal sensitivity", §3): times max(n_c . n_s, 0)^uNormalPower.
// Geometry (issue 12): times exp(-0.5 (plane distance / (uPlaneSigma x footprint))^2), the
// plane distance being |n_c . (p_s - p_c)|, the sample's distance from the centre's tangent
// plane, and the footprint the world size of one pixel at the centre. Depth differences
// alone let a plate's lit top 0.06 above the ground bleed into the dark strip under its edge
// (the eye sees both at nearly the same distance); the tangent plane separates them.
// Penumbra width (issue 12): a screen-space blur wider than the penumbra smears a sharp
// shadow (contact, a tiny light). Each shadowed pixel estimates its penumbra's width from
// classify's bounds as PCSS does (Fernando 2005): w = light size x (d_r - d_b) / d_b, with d
// the distance from the light plane of the receiver and of the nearest occluder its rays can
// meet (zNearMin), in pixels at the receiver; a pair's Gaussian sigma is at most
// uPenumbraScale x the smaller width of the two pixels (lit pixels set no limit), and the
// Gaussian is cut at 2 sigma (the radius, without that limit). A tap farther than the
// penumbra is wide lies on its lit or umbra side: a penumbra narrower than a pixel (a contact
// plate at auto's 2048^2) is not blurred at all, where the tail of a 0.4-pixel Gaussian
// still added 4% of each lit neighbour per pass to the umbra (issue 12: filtered 0.034
// against 0.014 unfiltered).
#include "shared/screen_pass.glsl"
#include "shared/filter_layout.h"
#include "shared/filter_tiles.glsl"
layout(binding = FILTER_SOURCE_UNIT) uniform sampler2D sourceTexture;
layout(binding = FILTER_WS_POSITION_UNIT) uniform sampler2D wsPositionTexture;
layout(binding = FILTER_WS_NORMAL_UNIT) uniform sampler2D wsNormalTexture;
layout(binding = FILTER_ZRANGE_UNIT) uniform sampler2D zRangeTexture;  // zNearMin, .., .., receiver
layout(binding = FILTER_TARGET_IMAGE, r32f) uniform writeonly image2D targetImage;
layout(location = FILTER_DIRECTION_LOCATION) uniform ivec2 uDirection;
layout(location = FILTER_RADIUS_LOCATION) uniform int uRadius;
layout(location = FILTER_DEPTH_SCALE_LOCATION) uniform float uDepthScale;
layout(location = FILTER_NORMAL_POWER_LOCATION) uniform float uNormalPower;  // 0: normals ignored
layout(location = FILTER_PLANE_SIGMA_LOCATION) uniform float uPlaneSigma;    // 0: plane distance ignored
layout(location = FILTER_PIXEL_ANGLE_LOCATION) uniform float uPixelAngle;    // 2 tan(fovY / 2) / eye height
layout(location = FILTER_PENUMBRA_SCALE_LOCATION) uniform float uPenumbraScale;  // 0: width ignored

// Estimated penumbra width at a pixel, in pixels (1e30: no limit: lit, or nothing known).
float penumbraPixels(ivec2 at, vec3 wsPosition) {
  vec4 zRange = texelFetch(zRangeTexture, at, 0);
  float occluder = zRange.x, receiver = zRange.w;
  if (!(occluder > 0.0 && occluder < receiver)) return 1e30;
  float lightSize = 2.0 * max(light.wsLightRight.w, light.wsLightUp.w);
  float wsWidth = lightSize * (receiver - occluder) / occluder;
  return wsWidth / (distance(wsPosition, frame.wsEyePosition.xyz) * uPixelAngle);
}

void main() {
  ivec2 pixel = filteredPixel();
  if (pixel.x < 0) return;
  vec4 center = texelFetch(wsPositionTexture, pixel, 0);
  float centerValue = texelFetch(sourceTexture, pixel, 0).r;
  if (center.w == 0.0 || uRadius == 0) {
    imageStore(targetImage, pixel, vec4(centerValue));
    return;
  }
  vec3 eye = frame.wsEyePosition.xyz;
  float centerDepth = distance(center.xyz, eye);
  vec3 centerNormal = texelFetch(wsNormalTexture, pixel, 0).xyz;
  float sigma = max(0.5 * float(uRadius), 0.5);
  float planeTolerance = uPlaneSigma * centerDepth * uPixelAngle;
  float centerWidth = uPenumbraScale <= 0.0 ? 1e30 : penumbraPixels(pixel, center.xyz);
  float sum = 0.0, weightSum = 0.0;
  for (int k = -uRadius; k <= uRadius; ++k) {
    ivec2 at = pixel + k * uDirection;
    if (any(lessThan(at, ivec2(0))) || any(greaterThanEqual(at, ivec2(frame.sizes.xy)))) continue;
    vec4 position = texelFetch(wsPositionTexture, at, 0);
    if (position.w == 0.0) continue;  // never blur the background into a shadow
    float pairSigma = uPenumbraScale <= 0.0 ? sigma
        : min(sigma, uPenumbraScale * min(centerWidth, penumbraPixels(at, position.xyz)));
    if (float(abs(k)) > 2.0 * pairSigma) continue;
    float weight = exp(-0.5 * float(k * k) / max(pairSigma * pairSigma, 1e-6));
    weight /= 1.0 + uDepthScale * abs(distance(position.xyz, eye) - centerDepth);
    if (uNormalPower > 0.0)
      weight *= pow(max(dot(centerNormal, texelFetch(wsNormalTexture, at, 0).xyz), 0.0), uNormalPower);
    if (uPlaneSigma > 0.0) {
      float plane = dot(centerNormal, position.xyz - center.xyz) / planeTolerance;
      weight *= exp(-0.5 * plane * plane);
    }
    sum += weight * texelFetch(sourceTexture, at, 0).r;
    weightSum += weight;
  }
  // The center always contributes weight 1, so weightSum > 0.
  imageStore(targetImage, pixel, vec4(clamp(sum / weightSum, 0.0, 1.0)));
}

// Stage `filter` (thesis §3, Fig 3.2e): one direction of the separable depth-sensitive
// Gaussian. A sample's weight is the Gaussian weight divided by (1 + |depth difference|)
// ("inversely proportional to the difference between its depth and that of the central
// sample (plus 1 to prevent division by zero)"); the depth is the distance from the eye,
// scaled by uDepthScale. Optionally normal-sensitive ("a robust implementation would also
// include normal sensitivity", §3): times max(n_c . n_s, 0)^uNormalPower.
#include "shared/screen_pass.glsl"
#include "shared/filter_layout.h"
#include "shared/filter_tiles.glsl"
layout(binding = FILTER_SOURCE_UNIT) uniform sampler2D sourceTexture;
layout(binding = FILTER_WS_POSITION_UNIT) uniform sampler2D wsPositionTexture;
layout(binding = FILTER_WS_NORMAL_UNIT) uniform sampler2D wsNormalTexture;
layout(binding = FILTER_TARGET_IMAGE, r32f) uniform writeonly image2D targetImage;
layout(location = FILTER_DIRECTION_LOCATION) uniform ivec2 uDirection;
layout(location = FILTER_RADIUS_LOCATION) uniform int uRadius;
layout(location = FILTER_DEPTH_SCALE_LOCATION) uniform float uDepthScale;
layout(location = FILTER_NORMAL_POWER_LOCATION) uniform float uNormalPower;  // 0: normals ignored

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
  float sum = 0.0, weightSum = 0.0;
  for (int k = -uRadius; k <= uRadius; ++k) {
    ivec2 at = pixel + k * uDirection;
    if (any(lessThan(at, ivec2(0))) || any(greaterThanEqual(at, ivec2(frame.sizes.xy)))) continue;
    vec4 position = texelFetch(wsPositionTexture, at, 0);
    if (position.w == 0.0) continue;  // never blur the background into a shadow
    float weight = exp(-0.5 * float(k * k) / (sigma * sigma));
    weight /= 1.0 + uDepthScale * abs(distance(position.xyz, eye) - centerDepth);
    if (uNormalPower > 0.0)
      weight *= pow(max(dot(centerNormal, texelFetch(wsNormalTexture, at, 0).xyz), 0.0), uNormalPower);
    sum += weight * texelFetch(sourceTexture, at, 0).r;
    weightSum += weight;
  }
  // The center always contributes weight 1, so weightSum > 0.
  imageStore(targetImage, pixel, vec4(clamp(sum / weightSum, 0.0, 1.0)));
}

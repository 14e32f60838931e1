// Stage `filter` (thesis §3, Fig 3.2e): one direction of the separable depth-sensitive
// Gaussian. A sample's weight is the Gaussian weight divided by (1 + |depth difference|)
// ("inversely proportional to the difference between its depth and that of the central
// sample (plus 1 to prevent division by zero)"); the depth is the distance from the eye,
// scaled by uDepthScale. Optionally normal-sensitive ("a robust implementation would also
// include normal sensitivity", §3): times max(n_c . n_s, 0)^uNormalPower.
//
// Each 8x8 group first loads the strip of pixels its taps reach (value, eye distance,
// normal) into shared memory once, so a tap costs no texture fetch: on llvmpipe this makes
// the pass several times faster than fetching per tap.
#include "shared/screen_pass.glsl"
layout(binding = 0) uniform sampler2D sourceTexture;
layout(binding = 1) uniform sampler2D wsPositionTexture;
layout(binding = 2) uniform sampler2D wsNormalTexture;
layout(binding = 0, r32f) uniform writeonly image2D targetImage;
layout(location = 1) uniform ivec2 uDirection;  // (1, 0) or (0, 1)
layout(location = 2) uniform int uRadius;       // <= kMaxRadius
layout(location = 3) uniform float uDepthScale;
layout(location = 4) uniform float uNormalPower;  // 0: normals ignored

const int kMaxRadius = 32;
const int kStrip = 8 + 2 * kMaxRadius;
// Per group: 8 lines (rows or columns) of up to kStrip samples each.
shared vec2 sValueDepth[8][kStrip];  // x = value, y = eye distance (-1: background/outside)
shared vec3 sNormal[8][kStrip];

void main() {
  // 1. The group's strip: line = the invocation's position across the filter direction,
  //    slot = position along it, from the group's first pixel minus the radius.
  ivec2 local = ivec2(gl_LocalInvocationID.xy);
  int line = uDirection.x == 1 ? local.y : local.x;
  int along = uDirection.x == 1 ? local.x : local.y;
  ivec2 groupOrigin = ivec2(gl_WorkGroupID.xy) * 8 + ivec2(0, uRowOffset);
  int count = 8 + 2 * uRadius;
  vec3 eye = frame.wsEyePosition.xyz;
  for (int slot = along; slot < count; slot += 8) {
    ivec2 at = groupOrigin + (uDirection.x == 1 ? ivec2(slot - uRadius, line) : ivec2(line, slot - uRadius));
    vec2 valueDepth = vec2(0.0, -1.0);
    vec3 normal = vec3(0.0);
    if (all(greaterThanEqual(at, ivec2(0))) && all(lessThan(at, ivec2(frame.sizes.xy)))) {
      vec4 position = texelFetch(wsPositionTexture, at, 0);
      valueDepth = vec2(texelFetch(sourceTexture, at, 0).r,
                        position.w == 0.0 ? -1.0 : distance(position.xyz, eye));
      if (uNormalPower > 0.0) normal = texelFetch(wsNormalTexture, at, 0).xyz;
    }
    sValueDepth[line][slot] = valueDepth;
    sNormal[line][slot] = normal;
  }
  barrier();

  // 2. The weighted sum over the taps.
  ivec2 pixel = screenPixel();
  if (pixel.x < 0) return;
  int center = along + uRadius;
  vec2 centerSample = sValueDepth[line][center];
  if (centerSample.y < 0.0 || uRadius == 0) {  // background: unfiltered
    imageStore(targetImage, pixel, vec4(centerSample.x));
    return;
  }
  vec3 centerNormal = sNormal[line][center];
  float sigma = max(0.5 * float(uRadius), 0.5);
  float sum = 0.0, weightSum = 0.0;
  for (int k = -uRadius; k <= uRadius; ++k) {
    vec2 tap = sValueDepth[line][center + k];
    if (tap.y < 0.0) continue;  // never blur the background into a shadow
    float weight = exp(-0.5 * float(k * k) / (sigma * sigma));
    weight /= 1.0 + uDepthScale * abs(tap.y - centerSample.y);
    if (uNormalPower > 0.0)
      weight *= pow(max(dot(centerNormal, sNormal[line][center + k]), 0.0), uNormalPower);
    sum += weight * tap.x;
    weightSum += weight;
  }
  // The center always contributes weight 1, so weightSum > 0.
  imageStore(targetImage, pixel, vec4(clamp(sum / weightSum, 0.0, 1.0)));
}

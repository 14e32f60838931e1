// Stage `filter` (thesis §3, Fig 3.2e): one direction of the separable depth-sensitive
// Gaussian. A sample's weight is the Gaussian weight divided by (1 + |depth difference|)
// ("inversely proportional to the difference between its depth and that of the central
// sample (plus 1 to prevent division by zero)"); the depth is the distance from the eye,
// scaled by uDepthScale. Optionally normal-sensitive ("a robust implementation would also
// include normal sensitivity", §3): times max(n_c . n_s, 0)^uNormalPower.
// Geometry: times exp(-0.5 (plane distance / (uPlaneSigma x footprint))^2), the
// plane distance being |n_c . (p_s - p_c)|, the sample's distance from the centre's tangent
// plane, and the footprint the world size of one pixel at the centre. Depth differences
// alone let a plate's lit top 0.06 above the ground bleed into the dark strip under its edge
// (the eye sees both at nearly the same distance); the tangent plane separates them.
// Penumbra width: a screen-space blur wider than the penumbra smears a sharp
// shadow (contact, a tiny light, a small occluder). Each shadowed pixel bounds its
// penumbra's width from classify's bounds with PCSS's formula (Fernando 2005): w = light
// size x (d_r - d_b) / d_b, d the distance from the light plane of the receiver and of an
// occluder, in pixels at the receiver. The kernel needs the narrowest penumbra an occluder
// its rays can meet may cast there: the deepest one, the far layer's zFarMax (a box's
// bottom, not its top), where it lies in front of the receiver; else (the receiver is one
// of the casters, so its own far side is deeper) the nearest, zNearMin, as PCSS does. The
// nearest alone made the cap several times too wide under a small box, where the ground's
// penumbra beside it is cast by its bottom edges, and it never bound
// (docs/decisions/096-filter-width-from-the-deepest-occluder.md). A pair's Gaussian sigma is at most
// uPenumbraScale x the smaller width of the two pixels (lit pixels set no limit), and the
// Gaussian is cut at 2 sigma (the radius, without that limit). A tap farther than the
// penumbra is wide lies on its lit or umbra side: a penumbra narrower than a pixel (a contact
// plate at auto's 2048^2) is not blurred at all, where the tail of a 0.4-pixel Gaussian
// still added 4% of each lit neighbour per pass to the umbra (filtered 0.034
// against 0.014 unfiltered).
// One pixel per invocation; the 8 x 8 workgroup filters one tile (filter_tiles.glsl). A
// separable pass is bound by its reads: every pixel of a row needs the same taps along the
// row, so the group first reads its 8 rows, grown by the radius at both ends (the apron),
// into shared memory, each tap once, with the tap's eye distance and penumbra width worked
// out there; then each invocation adds its own pixel's taps k = -r .. r from shared memory.
#include "shared/frame.glsl"
#include "stages/monte_carlo/filter/filter_layout.h"
#include "filter_tiles.glsl"
layout(local_size_x = FILTER_TILE_SIZE, local_size_y = FILTER_TILE_SIZE) in;
layout(binding = FILTER_SOURCE_UNIT) uniform sampler2D sourceImage;
layout(binding = FILTER_WS_POSITION_UNIT) uniform sampler2D wsPositionImage;
layout(binding = FILTER_WS_NORMAL_UNIT) uniform sampler2D wsNormalImage;
layout(binding = FILTER_ZRANGE_UNIT) uniform sampler2D zRangeImage;  // zNearMin, .., .., receiver
layout(binding = FILTER_TARGET_IMAGE, r32f) uniform writeonly image2D targetImage;
layout(location = FILTER_DIRECTION_LOCATION) uniform ivec2 uDirection;
layout(location = FILTER_RADIUS_LOCATION) uniform int uRadius;
layout(location = FILTER_DEPTH_SCALE_LOCATION) uniform float uDepthScale;
layout(location = FILTER_NORMAL_POWER_LOCATION) uniform float uNormalPower;  // 0: normals ignored
layout(location = FILTER_PLANE_SIGMA_LOCATION) uniform float uPlaneSigma;    // 0: plane distance ignored
layout(location = FILTER_PIXEL_ANGLE_LOCATION) uniform float uPixelAngle;    // 2 tan(fovY / 2) / eye height
layout(location = FILTER_PENUMBRA_SCALE_LOCATION) uniform float uPenumbraScale;  // 0: width ignored

// The group's rows of taps along the pass's direction: row `across` (0..7), tap `along`
// (0 .. 8 + 2r - 1: the tile's first pixel minus r, to its last plus r).
const int kRowTaps = FILTER_TILE_SIZE + 2 * FILTER_MAX_RADIUS;
shared vec4 tapPosition[FILTER_TILE_SIZE * kRowTaps];  // xyz world position, w eye distance
shared vec4 tapNormal[FILTER_TILE_SIZE * kRowTaps];    // xyz normal, w penumbra width (pixels)
shared vec2 tapValue[FILTER_TILE_SIZE * kRowTaps];     // x visibility, y 1: a receiver, 0: not

// The narrowest penumbra width at a pixel, in pixels (1e30: no limit: lit, or nothing known).
float penumbraPixels(ivec2 at, vec3 wsPosition) {
  vec4 zRange = texelFetch(zRangeImage, at, 0);
  float occluder = zRange.x, deepest = zRange.z, receiver = zRange.w;
  if (!(occluder > 0.0 && occluder < receiver)) return 1e30;
  if (deepest > occluder && deepest < receiver) occluder = deepest;  // the narrowest penumbra
  float lightSize = 2.0 * max(light.wsLightRight.w, light.wsLightUp.w);
  float wsWidth = lightSize * (receiver - occluder) / occluder;
  return wsWidth / (distance(wsPosition, frame.wsEyePosition.xyz) * uPixelAngle);
}

// Reads one tap into shared memory; a pixel off the image or on the background is no tap
// (never blurred into a shadow).
void loadTap(int slot, ivec2 at, ivec2 size) {
  tapValue[slot] = vec2(0.0);
  if (any(lessThan(at, ivec2(0))) || any(greaterThanEqual(at, size))) return;
  vec4 position = texelFetch(wsPositionImage, at, 0);
  if (position.w == 0.0) return;
  float width = uPenumbraScale <= 0.0 ? 1e30 : penumbraPixels(at, position.xyz);
  tapPosition[slot] = vec4(position.xyz, distance(position.xyz, frame.wsEyePosition.xyz));
  tapNormal[slot] = vec4(texelFetch(wsNormalImage, at, 0).xyz, width);
  tapValue[slot] = vec2(texelFetch(sourceImage, at, 0).r, 1.0);
}

void main() {
  // 1. The tile, and this invocation's pixel: `along` the pass's direction and `across` it.
  ivec2 tile = filteredTile(), across = uDirection.yx;
  ivec2 size = ivec2(frame.sizes.xy);
  int pixelAlong = int(dot(vec2(gl_LocalInvocationID.xy), vec2(uDirection)));
  int pixelAcross = int(dot(vec2(gl_LocalInvocationID.xy), vec2(across)));
  ivec2 pixel = tile + pixelAlong * uDirection + pixelAcross * across;

  // 2. The group's taps into shared memory: 8 rows of 8 + 2r, every invocation reading every
  //    64th of them.
  int rowTaps = FILTER_TILE_SIZE + 2 * uRadius;
  for (int slot = int(gl_LocalInvocationIndex); slot < FILTER_TILE_SIZE * rowTaps;
       slot += FILTER_TILE_SIZE * FILTER_TILE_SIZE) {
    int row = slot / rowTaps, along = slot % rowTaps - uRadius;
    loadTap(row * kRowTaps + along + uRadius, tile + along * uDirection + row * across, size);
  }
  memoryBarrierShared();
  barrier();
  if (any(greaterThanEqual(pixel, size))) return;

  // 3. The weighted sum over the taps k = -r .. r of this pixel's row (its centre is k = 0).
  float centerValue = texelFetch(sourceImage, pixel, 0).r;
  int center = pixelAcross * kRowTaps + pixelAlong + uRadius;
  if (tapValue[center].y == 0.0 || uRadius == 0) {  // the background, or no blur: as it was
    imageStore(targetImage, pixel, vec4(centerValue));
    return;
  }
  vec3 centerPosition = tapPosition[center].xyz, centerNormal = tapNormal[center].xyz;
  float centerDepth = tapPosition[center].w, centerWidth = tapNormal[center].w;
  float tolerance = uPlaneSigma * centerDepth * uPixelAngle;  // the tangent plane's
  float sigma = max(0.5 * float(uRadius), 0.5);
  float sum = 0.0, weightSum = 0.0;
  for (int k = -uRadius; k <= uRadius; ++k) {
    int slot = center + k;
    if (tapValue[slot].y == 0.0) continue;
    float pairSigma = uPenumbraScale <= 0.0 ? sigma : min(sigma, uPenumbraScale * min(centerWidth, tapNormal[slot].w));
    if (float(abs(k)) > 2.0 * pairSigma) continue;
    float weight = exp(-0.5 * float(k * k) / max(pairSigma * pairSigma, 1e-6));
    weight /= 1.0 + uDepthScale * abs(tapPosition[slot].w - centerDepth);
    if (uNormalPower > 0.0) weight *= pow(max(dot(centerNormal, tapNormal[slot].xyz), 0.0), uNormalPower);
    if (uPlaneSigma > 0.0) {
      float plane = dot(centerNormal, tapPosition[slot].xyz - centerPosition) / tolerance;
      weight *= exp(-0.5 * plane * plane);
    }
    sum += weight * tapValue[slot].x;
    weightSum += weight;
  }
  // 4. The result: the centre always contributes weight 1, so weightSum > 0.
  imageStore(targetImage, pixel, vec4(clamp(sum / weightSum, 0.0, 1.0)));
}

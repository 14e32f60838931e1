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
// Written for llvmpipe, where the pass is bound by its reads (issue 14): one invocation
// filters 4 consecutive pixels along the pass's direction, which share all but a few taps:
// each tap's position, normal, penumbra width and value are read once for the 4 (2r + 4
// taps where a pixel per invocation read 4 (2r + 1)). Each pixel still adds its taps in the
// order k = -r .. r with the same operations, so its result is bit for bit the same. The 4
// pixels' state is kept in vec4 components, not arrays (llvmpipe indexes private arrays
// lane by lane).
#define UNIFORM_BLOCKS_LOADED_AT_START  // frame.glsl: why
#include "shared/frame.glsl"
#include "shared/filter_layout.h"
#include "shared/filter_tiles.glsl"
#if FILTER_PIXELS_PER_INVOCATION != 4
#error "filter.comp keeps its pixels in vec4 components"
#endif
layout(local_size_x = FILTER_TILE_SIZE * FILTER_TILE_SIZE / 4) in;
layout(binding = FILTER_SOURCE_IMAGE, r32f) uniform readonly image2D sourceImage;
layout(binding = FILTER_WS_POSITION_IMAGE, rgba32f) uniform readonly image2D wsPositionImage;
layout(binding = FILTER_WS_NORMAL_IMAGE, rgba32f) uniform readonly image2D wsNormalImage;
layout(binding = FILTER_ZRANGE_IMAGE, rgba32f) uniform readonly image2D zRangeImage;  // zNearMin, .., .., receiver
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
  vec4 zRange = imageLoad(zRangeImage, at);
  float occluder = zRange.x, receiver = zRange.w;
  if (!(occluder > 0.0 && occluder < receiver)) return 1e30;
  float lightSize = 2.0 * max(light.wsLightRight.w, light.wsLightUp.w);
  float wsWidth = lightSize * (receiver - occluder) / occluder;
  return wsWidth / (distance(wsPosition, frame.wsEyePosition.xyz) * uPixelAngle);
}

// The 4 pixels' centres, component p for pixel p.
struct Centers {
  vec4 x, y, z, w;           // position
  vec4 nx, ny, nz;           // normal
  vec4 depth, tolerance, width;  // eye distance, tangent-plane tolerance, penumbra width
};
struct Tap {
  int j;  // offset from pixel 0 along the direction
  vec3 position;
  float depth, width, value;
  vec3 normal;
};

// Pixel p's weight of tap `tap` (k = tap.j - p), added to its sums.
void addTap(int p, Tap tap, Centers c, float sigma, inout vec4 sum, inout vec4 weightSum) {
  int k = tap.j - p;
  if (abs(k) > uRadius) return;
  float pairSigma = uPenumbraScale <= 0.0 ? sigma : min(sigma, uPenumbraScale * min(c.width[p], tap.width));
  if (float(abs(k)) > 2.0 * pairSigma) return;
  float weight = exp(-0.5 * float(k * k) / max(pairSigma * pairSigma, 1e-6));
  weight /= 1.0 + uDepthScale * abs(tap.depth - c.depth[p]);
  vec3 centerNormal = vec3(c.nx[p], c.ny[p], c.nz[p]);
  if (uNormalPower > 0.0) weight *= pow(max(dot(centerNormal, tap.normal), 0.0), uNormalPower);
  if (uPlaneSigma > 0.0) {
    float plane = dot(centerNormal, tap.position - vec3(c.x[p], c.y[p], c.z[p])) / c.tolerance[p];
    weight *= exp(-0.5 * plane * plane);
  }
  sum[p] += weight * tap.value;
  weightSum[p] += weight;
}

// Tap j (offset from pixel 0 along the direction); false off the image or on the background
// (never blurred into a shadow).
bool readTap(ivec2 first, int j, ivec2 size, vec3 eye, out Tap tap) {
  ivec2 at = first + j * uDirection;
  tap = Tap(j, vec3(0.0), 0.0, 0.0, 0.0, vec3(0.0));
  if (any(lessThan(at, ivec2(0))) || any(greaterThanEqual(at, size))) return false;
  vec4 position = imageLoad(wsPositionImage, at);
  if (position.w == 0.0) return false;
  tap = Tap(j, position.xyz, distance(position.xyz, eye),
            uPenumbraScale <= 0.0 ? 1e30 : penumbraPixels(at, position.xyz),
            imageLoad(sourceImage, at).r, imageLoad(wsNormalImage, at).xyz);
  return true;
}

void main() {
  loadFrameBlocks();
  // 1. This invocation's pixels: 4 consecutive ones along the direction, in the tile its
  //    group covers; lanes next to each other take neighbouring rows (columns).
  uint lane = gl_LocalInvocationIndex;
  ivec2 first = filteredTile() + int(lane / uint(FILTER_TILE_SIZE)) * 4 * uDirection +
                int(lane % uint(FILTER_TILE_SIZE)) * uDirection.yx;
  ivec2 size = ivec2(frame.sizes.xy);
  vec3 eye = frame.wsEyePosition.xyz;
  float sigma = max(0.5 * float(uRadius), 0.5);

  // 2. The centres.
  Centers c;
  for (int p = 0; p < 4; ++p) {
    ivec2 pixel = first + p * uDirection;
    vec4 center = imageLoad(wsPositionImage, pixel);
    vec3 normal = imageLoad(wsNormalImage, pixel).xyz;
    c.x[p] = center.x, c.y[p] = center.y, c.z[p] = center.z, c.w[p] = center.w;
    c.nx[p] = normal.x, c.ny[p] = normal.y, c.nz[p] = normal.z;
    c.depth[p] = distance(center.xyz, eye);
    c.tolerance[p] = uPlaneSigma * c.depth[p] * uPixelAngle;
    c.width[p] = uPenumbraScale <= 0.0 ? 1e30 : penumbraPixels(pixel, center.xyz);
  }

  // 3. The taps j = -r .. r + 3, each read once; pixel p takes tap j as its k = j - p where
  //    |k| <= r, so each pixel adds its taps in the order k = -r .. r. Tap j reaches pixels
  //    max(0, j - r) .. min(3, j + r): the first three taps and the last three reach fewer
  //    than four, and are added to those alone, outside the loop (llvmpipe runs a call that
  //    returns at once for all lanes as one that does not): 8r + 4 pixel-taps, not 8r + 16.
  //    Where r < 2 the loop has no tap (guarded); at r = 0 two of the first three taps are
  //    also among the last three (guarded there).
  vec4 sum = vec4(0.0), weightSum = vec4(0.0);
  Tap tap;
  if (readTap(first, -uRadius, size, eye, tap)) addTap(0, tap, c, sigma, sum, weightSum);
  if (readTap(first, 1 - uRadius, size, eye, tap)) {
    addTap(0, tap, c, sigma, sum, weightSum);
    addTap(1, tap, c, sigma, sum, weightSum);
  }
  if (readTap(first, 2 - uRadius, size, eye, tap)) {
    addTap(0, tap, c, sigma, sum, weightSum);
    addTap(1, tap, c, sigma, sum, weightSum);
    addTap(2, tap, c, sigma, sum, weightSum);
  }
  int j = 3 - uRadius;
  do {  // tested at the bottom, as the loops of classify.frag
    if (j <= uRadius && readTap(first, j, size, eye, tap)) {
      addTap(0, tap, c, sigma, sum, weightSum);
      addTap(1, tap, c, sigma, sum, weightSum);
      addTap(2, tap, c, sigma, sum, weightSum);
      addTap(3, tap, c, sigma, sum, weightSum);
    }
  } while (++j <= uRadius);
  if (uRadius >= 1 && readTap(first, uRadius + 1, size, eye, tap)) {
    addTap(1, tap, c, sigma, sum, weightSum);
    addTap(2, tap, c, sigma, sum, weightSum);
    addTap(3, tap, c, sigma, sum, weightSum);
  }
  if (uRadius >= 1 && readTap(first, uRadius + 2, size, eye, tap)) {
    addTap(2, tap, c, sigma, sum, weightSum);
    addTap(3, tap, c, sigma, sum, weightSum);
  }
  if (readTap(first, uRadius + 3, size, eye, tap)) addTap(3, tap, c, sigma, sum, weightSum);

  // 4. The results: a background pixel, or any pixel with radius 0, keeps its value; the
  //    centre always contributes weight 1 otherwise, so weightSum > 0.
  for (int p = 0; p < 4; ++p) {
    ivec2 pixel = first + p * uDirection;
    if (any(greaterThanEqual(pixel, size))) continue;
    float centerValue = imageLoad(sourceImage, pixel).r;
    bool keep = c.w[p] == 0.0 || uRadius == 0;
    imageStore(targetImage, pixel, vec4(keep ? centerValue : clamp(sum[p] / weightSum[p], 0.0, 1.0)));
  }
}

// Stage `classify` (thesis §3.6, Eq 3.3, Fig 3.7-3.8): per eye pixel, bounds on the
// occluder depths that any ray from the light to the receiver can meet, refined by
// iterating Eq 3.3 over the N-buffer (exact bounds) or the min-max mipmap (conservative
// bounds), and the class they imply:
//   lit      receiver depth <= zNearMin: nothing can block any ray. No bias is subtracted:
//            a ray's end moves towards the light by the trace's bias along the *ray*, which
//            may be almost parallel to the map, so the receiver's own depth is the only
//            bound on the deepest end point that holds for every ray;
//   umbra    receiver depth minus the largest bias any ray gets (light.bias + Eq 3.2 with
//            n.l at its clamp) >= zNearMax: every ray ends behind the near layer (valid for
//            a single-layer height field; off with three layers, §3.6);
//   penumbra otherwise; outside: the receiver is not in the light's frustum.
// Step 1 of 2: a fragment shader over the image writing the class and the bounds
// (app/gl/screen_triangle.h: why not a compute pass); classify_list.comp then counts the
// classes and lists the pixels that need rays.
#include "shared/frame.glsl"
#include "shared/bias.glsl"
#include "shared/nbuffer.glsl"
#include "shared/minmax.glsl"
#include "classify.glsl"
#include "shared/classes.h"
#include "stages/monte_carlo/classify/classify_layout.h"
layout(binding = CLASSIFY_WS_POSITION_UNIT) uniform sampler2D wsPositionTexture;
layout(binding = CLASSIFY_WS_NORMAL_UNIT) uniform sampler2D wsNormalTexture;
layout(binding = CLASSIFY_LEVELS_UNIT) uniform sampler2DArray nbufferLevels;
layout(binding = CLASSIFY_MINMAX_UNIT) uniform sampler2D minmaxLevels;  // level n >= 1: mip n - 1
layout(binding = CLASSIFY_NEAR_UNIT) uniform sampler2D nearLayer;
layout(binding = CLASSIFY_FAR_UNIT) uniform sampler2D farLayer;
layout(location = 0) out float maskOut;   // the class
layout(location = 1) out vec4 zRangeOut;  // zNearMin, zNearMax, zFarMax, receiver lsDepth
layout(location = CLASSIFY_ITERATIONS_LOCATION) uniform int uIterations;
layout(location = CLASSIFY_UMBRA_TEST_LOCATION) uniform bool uUmbraTest;
layout(location = CLASSIFY_MINMAX_CELLS_LOCATION) uniform int uMinMaxCells;
// The stage compiles one program per hierarchy, CLASSIFY_OVER_MINMAX 0 (N-buffer, §3.5) or
// 1 (min-max mipmap), so each reads as the one hierarchy it walks.
#if !defined(CLASSIFY_OVER_MINMAX)
#error "classify.frag is compiled with CLASSIFY_OVER_MINMAX 0 or 1 (stages/monte_carlo/classify/classify.cpp)"
#endif

bool wholeLightInFront(vec3 wsPosition, vec3 wsNormal) {
  vec3 right = light.wsLightRight.w * light.wsLightRight.xyz, up = light.wsLightUp.w * light.wsLightUp.xyz;
  vec3 toCenter = light.wsLightCenter.xyz - wsPosition;
  float centre = dot(wsNormal, toCenter), spread = abs(dot(wsNormal, right)) + abs(dot(wsNormal, up));
  return centre - spread > 0.0;  // the least n . (corner - p) over the four corners
}

// Bounds over the texel rectangle [lo, hi] from the chosen hierarchy.
vec3 boundsOverRect(ivec2 lo, ivec2 hi, ivec2 mapSize) {
  return CLASSIFY_OVER_MINMAX != 0
             ? minmaxBoundsOverRect(minmaxLevels, nearLayer, farLayer, lo, hi, mapSize, uMinMaxCells)
             : nbufferBoundsOverRect(nbufferLevels, lo, hi);
}

// Eq 3.3 iterated over the region any ray to point a or point b (map coordinates, light
// depth) can cross: the union of the two squares. For the points between a and b the
// squares' corners move monotonically, so the union holds them too (within the 0.01-texel
// margin of reachableTexels). Each iteration is one application of Eq 3.3: the nearest
// occluder depth found so far shrinks the region, whose bounds are then read again; it
// stops after uIterations, or once no ray can end deeper than zNearMin (lit for sure).
vec3 boundsForRays(vec3 a, vec3 b, vec3 bounds, ivec2 mapSize) {
  float deepestEnd = zToLsDepth(max(a.z, b.z));  // the deepest any ray can end
  for (int i = 0; i < uIterations && deepestEnd > bounds.x; ++i) {
    float occluderZ = lsDepthToZ(bounds.x);
    ivec4 ra = reachableTexels(a.xy, a.z, occluderZ, mapSize);
    ivec4 rb = reachableTexels(b.xy, b.z, occluderZ, mapSize);
    vec3 refined = boundsOverRect(min(ra.xy, rb.xy), max(ra.zw, rb.zw), mapSize);
    // Each region lies inside the previous one, so every bound found so far still holds:
    // keep the tightest (zNearMin monotone up, the maxima monotone down).
    bounds = vec3(max(bounds.x, refined.x), min(bounds.yz, refined.yz));
  }
  return bounds;
}

// Writes the bounds (zNearMin, zNearMax, zFarMax, receiver lsDepth) and returns the class.
// The receiver point moves along its normal by an offset capped by zNearMin (bias.glsl),
// which the trace recomputes from the zNearMin written here, so the two must agree and the
// bounds must hold at that point: first the bounds at the fully offset point; where they cap
// the offset, the bounds over every point from none to the full offset instead (a lower
// zNearMin, so a cap at most as tight, valid wherever it puts the point).
int classify(vec3 wsPosition, vec3 wsNormal, out vec4 zRange) {
  ivec2 size = ivec2(light.mapSize.xy);
  // The coarsest level's window (the min-max mipmap's one top cell) is the whole map: the
  // starting bounds (§3.6).
  vec3 whole = CLASSIFY_OVER_MINMAX != 0
                   ? minmaxBoundsOverRect(minmaxLevels, nearLayer, farLayer, ivec2(0), size - 1, size, 1)
                   : nbufferWholeMap(nbufferLevels);
  // The point's own map coordinates, once: every offset below is worked out from them.
  vec3 pointMap = lightMapCoords(wsPosition);
  float fullOffset = fullNormalOffset(pointMap.z);
  vec3 map = lightMapCoords(wsPosition + wsNormal * fullOffset);
  zRange = vec4(whole, zToLsDepth(map.z));
  bool insideMap = all(greaterThanEqual(map.xy, vec2(0.0))) && all(lessThan(map.xy, vec2(1.0)))
                   && map.z > light.lightDepthRange.x;
  if (!insideMap) {
    zRange.w = isinf(zRange.w) || isnan(zRange.w) ? 0.0 : zRange.w;
    return CLASS_OUTSIDE;
  }
  vec3 bounds = boundsForRays(map, map, whole, size);
  // The bounds cap the offset: then bound the rays from every point between the original
  // and the fully offset one instead.
  if (normalOffsetDistance(pointMap.z, wsNormal, bounds.x) < fullOffset)
    bounds = boundsForRays(map, pointMap, whole, size);
  zRange.xyz = bounds;
  // The capped point (the trace starts its rays there too).
  wsPosition = normalOffsetPoint(wsPosition, pointMap.z, wsNormal, bounds.x);
  float receiverZ = lightMapCoords(wsPosition).z;
  float largestBias = light.bias.x;
  if (light.bias.y != 0.0) largestBias += adaptiveBias(receiverZ, vec3(0.0), vec3(0.0), light.bias.z);
  float endLsDepth = zToLsDepth(receiverZ);                 // the deepest any ray can end
  float shallowestEnd = zToLsDepth(receiverZ - largestBias);  // the shallowest
  zRange.w = endLsDepth;
  // Lit also needs the whole light in front of the tangent plane: a sample behind it is
  // blocked (the trace's backface early out, the reference), so a pixel that sees only part
  // of the light (a box's side face) is penumbra, not lit (the oracle: side faces of
  // a box were 0.8 too bright).
  if (endLsDepth <= bounds.x && wholeLightInFront(wsPosition, wsNormal)) return CLASS_LIT;
  if (uUmbraTest && shallowestEnd >= bounds.y) return CLASS_UMBRA;
  return CLASS_PENUMBRA;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 wsPosition = texelFetch(wsPositionTexture, pixel, 0);
  // Background: the targets were cleared to its class and bounds (all 0) in the draw, and a
  // discarded fragment writes nothing.
  if (wsPosition.w == 0.0) discard;
  vec4 zRange;
  maskOut = float(classify(wsPosition.xyz, texelFetch(wsNormalTexture, pixel, 0).xyz, zRange));
  zRangeOut = zRange;
}

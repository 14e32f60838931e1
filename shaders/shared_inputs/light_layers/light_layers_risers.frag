// Stage `light_layers`, last step: a zero-thickness sheet's texel spans the depths of its
// plane over the texel's footprint (thesis §3.3: the layers bound the occluder's volume,
// Fig 3.4). A tilted sheet stored at texel centres is a staircase with near == far on every
// step; a ray that crosses the sheet between two steps' depths at their common edge met
// neither step and passed through (1-4% of the rays, +0.011 mean visibility where the exact
// value is below 0.1, on a sheet tilted 35 degrees). Here a sheet texel (far - near below
// kSheet) and each of its 4-neighbours that is a sheet texel of the same sheet meet at the
// midpoint of their two depths: the deeper one's near and the shallower one's far both
// become it (the same sum of the same two values, so where each counts the other as of its
// sheet the two steps meet exactly), which closes every riser. A neighbour is of the same sheet when it lies at most kMaxSlope texel
// widths deeper or shallower (a sheet tilted up to ~80 degrees), or where the plane of this
// texel's own surface (its slope, written by the far pass: light_layers.frag) puts it,
// within kPlaneTolerance of the step: a sheet nearly edge-on to the light rises tens of
// texel widths per texel (1 / tan of its angle from edge-on: 14 at 4 degrees), the same at
// every map size, and with the first rule alone its risers stayed open and rays slipped
// between nearly all of its steps (docs/accuracy.md, the edge-on sheet). Another occluder
// beside the sheet is joined only if it happens to lie on the sheet's plane. And where a
// sheet texel has no neighbour on one side (the ends of a steep sheet's image, 2-8 texels
// wide at a 256^2 map), its far reaches its plane's depth at the texel's deepest corner and
// its near at the shallowest, so neither end of the image is half a step short.
// Texels of closed or thick occluders (far > near), and texels with no occluder, keep what
// the near and far passes wrote.
// A fragment shader over the rectangle of the map the occluders can cover
// (stages/shared_inputs/light_layers/light_layers.cpp), discarding every texel but a sheet's: a discarded
// fragment writes nothing, so every other texel keeps what the passes wrote. It writes far
// as its colour and near as its depth, and reads the near layer as rasterized from a copy
// (a neighbour's near must be the rasterized one, not the one rewritten here).
#include "shared/frame.glsl"
#include "stages/shared_inputs/light_layers/light_layers_layout.h"
layout(binding = RISERS_NEAR_UNIT) uniform sampler2D nearLayer;     // the near pass's, copied
layout(binding = RISERS_FAR_UNIT) uniform sampler2D farRasterized;  // the far pass's depth buffer
layout(binding = RISERS_SLOPE_UNIT) uniform sampler2D farSlope;     // d(1/z) per texel, x and y
layout(location = 0) out float farOut;

const float kSheet = 1e-6, kMaxSlope = 6.0, kPlaneTolerance = 0.25;

bool isSheet(float nearDepth, float farDepth) {
  return farDepth >= nearDepth && farDepth - nearDepth <= kSheet;
}

// The lsDepth this texel's plane has at the centre of the texel `offset` away: 1 / z is
// affine across the map on a plane (light_layers.frag), so this is exact for a flat sheet.
// -1 where the plane does not reach that texel in front of the projection point.
float planeDepthAt(float z, vec2 slope, ivec2 offset) {
  float invZ = 1.0 / z + dot(slope, vec2(offset));
  return invZ > 0.0 ? zToLsDepth(1.0 / invZ) : -1.0;
}

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy), last = textureSize(farRasterized, 0) - 1;
  float nearDepth = texelFetch(nearLayer, texel, 0).r;
  float farDepth = texelFetch(farRasterized, texel, 0).r;
  if (!isSheet(nearDepth, farDepth)) discard;
  // One texel's width in world units at this depth, in lsDepth units.
  float z = lsDepthToZ(farDepth);
  float tanHalfFov = max(light.lightDepthRange.z, light.lightDepthRange.w);
  float texelWorld = 2.0 * z * tanHalfFov / float(last.x + 1);
  float cap = kMaxSlope * texelWorld / (light.lightDepthRange.y - light.lightDepthRange.x);
  vec2 slope = texelFetch(farSlope, texel, 0).rg;
  // The neighbours (left, below, above, right) that are sheet texels of this sheet: far
  // reaches the midpoint towards the deepest, near towards the shallowest. A neighbour past
  // the map's border is the texel itself, whose midpoint is the texel's own depth.
  const ivec2 offsets[4] = ivec2[4](ivec2(-1, 0), ivec2(0, -1), ivec2(0, 1), ivec2(1, 0));
  float raised = farDepth, lowered = nearDepth;
  for (int k = 0; k < 4; ++k) {
    ivec2 neighbour = clamp(texel + offsets[k], ivec2(0), last);
    float n = texelFetch(nearLayer, neighbour, 0).r, f = texelFetch(farRasterized, neighbour, 0).r;
    if (!isSheet(n, f)) continue;
    float onPlane = planeDepthAt(z, slope, offsets[k]);
    bool samePlane = onPlane >= 0.0 && abs(f - onPlane) <= kPlaneTolerance * abs(onPlane - farDepth);
    if (abs(f - farDepth) <= cap || samePlane) {
      float edge = 0.5 * (farDepth + f);
      raised = max(raised, edge);
      lowered = min(lowered, edge);
    }
  }
  // And at least the texel's footprint on its plane: its deepest corner for far, its
  // shallowest for near (1 / z falls with depth). On a flat sheet the corners reach a little
  // past the midpoints (they add the half-texel rise along both axes) and bound the ends of
  // the image, which have no neighbour on one side; the midpoints make two steps meet
  // exactly where the slope (16-bit) or the plane's prediction is off.
  vec2 corner = -0.5 * sign(slope);
  float invZ = 1.0 / z + dot(slope, corner);
  if (invZ > 0.0) raised = max(raised, zToLsDepth(1.0 / invZ));
  farOut = raised;
  float invZShallow = 1.0 / z - dot(slope, corner);
  gl_FragDepth = clamp(min(lowered, zToLsDepth(1.0 / invZShallow)), 0.0, 1.0);
}

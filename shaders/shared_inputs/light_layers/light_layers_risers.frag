// Stage `light_layers`, last step: the far layer of a zero-thickness sheet
// reaches down to its neighbours' depths. A tilted sheet stored at texel centres is a
// staircase with near == far on every step; a ray that crosses the sheet between two steps'
// depths at their common edge met neither step and passed through (1-4% of the rays, +0.011
// mean visibility where the exact value is below 0.1, on a sheet tilted 35 degrees). Here a
// sheet texel (far - near below kSheet) takes as far the largest depth of its 4-neighbours
// that are sheet texels of the same sheet, which closes every riser: the shallower step of
// each pair now spans the gap. A neighbour is of the same sheet when it lies at most
// kMaxSlope texel widths deeper (a sheet tilted up to ~80 degrees), or where the plane of
// this texel's own surface (its slope, written by the far pass: light_layers.frag) puts it,
// within kPlaneTolerance of the step: a sheet nearly edge-on to the light rises tens of
// texel widths per texel (1 / tan of its angle from edge-on: 14 at 4 degrees), the same at
// every map size, and with the first rule alone its risers stayed open and rays slipped
// between nearly all of its steps (docs/accuracy.md, the edge-on sheet). Another occluder
// beside the sheet is joined only if it happens to lie on the sheet's plane. And a sheet
// texel covers its footprint, not only its centre: its far reaches its plane's depth at the
// texel's deepest corner, so the deep end of a steep sheet's image (no deeper neighbour) is
// not half a step short. (The shallow end stays half a step short: near is not rewritten.)
// Texels of closed or thick occluders (far > near), and texels with no occluder, keep what
// the far pass wrote.
// A fragment shader over the rectangle of the map the occluders can cover
// (app/gl/screen_triangle.h), discarding every texel but a sheet's: a discarded fragment
// writes nothing, so every other texel keeps what the far pass wrote without a copy.
#include "shared/frame.glsl"
#include "stages/shared_inputs/light_layers/light_layers_layout.h"
layout(binding = RISERS_NEAR_UNIT) uniform sampler2D nearLayer;
layout(binding = RISERS_FAR_UNIT) uniform sampler2D farRasterized;  // the far pass's depth buffer
layout(binding = RISERS_SLOPE_UNIT) uniform sampler2D farSlope;     // d(1/z) per texel, x and y
layout(location = RISERS_CLOSE_LOCATION) uniform bool uCloseRisers;
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
  if (!uCloseRisers || !isSheet(nearDepth, farDepth)) discard;
  // One texel's width in world units at this depth, in lsDepth units.
  float z = lsDepthToZ(farDepth);
  float tanHalfFov = max(light.lightDepthRange.z, light.lightDepthRange.w);
  float texelWorld = 2.0 * z * tanHalfFov / float(last.x + 1);
  float cap = kMaxSlope * texelWorld / (light.lightDepthRange.y - light.lightDepthRange.x);
  vec2 slope = texelFetch(farSlope, texel, 0).rg;
  // The deepest neighbour (left, below, above, right) that is a sheet texel of this sheet.
  // A neighbour past the map's border is the texel itself, which never raises far (its far
  // is far itself).
  const ivec2 offsets[4] = ivec2[4](ivec2(-1, 0), ivec2(0, -1), ivec2(0, 1), ivec2(1, 0));
  float raised = farDepth;
  for (int k = 0; k < 4; ++k) {
    ivec2 neighbour = clamp(texel + offsets[k], ivec2(0), last);
    float n = texelFetch(nearLayer, neighbour, 0).r, f = texelFetch(farRasterized, neighbour, 0).r;
    if (!isSheet(n, f)) continue;
    float onPlane = planeDepthAt(z, slope, offsets[k]);
    bool samePlane = onPlane >= 0.0 && abs(f - onPlane) <= kPlaneTolerance * abs(onPlane - farDepth);
    if (f - farDepth <= cap || samePlane) raised = max(raised, f);
  }
  // The deepest corner of the texel's footprint on its plane (1 / z falls with depth).
  vec2 corner = -0.5 * sign(slope);
  float invZ = 1.0 / z + dot(slope, corner);
  if (invZ > 0.0) raised = max(raised, zToLsDepth(1.0 / invZ));
  farOut = raised;
}

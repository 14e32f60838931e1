// Shared by the raster4d passes (layouts and spaces: stages/raster4d/raster4d/raster4d_layout.h).
#include "stages/raster4d/raster4d/raster4d_layout.h"
layout(std140, binding = RASTER4D_PARAMS_BINDING) uniform Raster4dBlock { Raster4dParams r4d; };

// Floats as uints whose unsigned order is the float order (for atomicMin / atomicMax).
uint orderedFromFloat(float value) {
  uint bits = floatBitsToUint(value);
  return (bits & 0x80000000u) != 0u ? ~bits : bits | 0x80000000u;
}
float floatFromOrdered(uint bits) {
  return uintBitsToFloat((bits & 0x80000000u) != 0u ? bits & 0x7fffffffu : ~bits);
}

vec3 lightSpace(vec3 wsPoint) { return (r4d.lsFromWorld * vec4(wsPoint, 1.0)).xyz; }

// §3.1 Proj4 of a light-space point with d > 0: (min xy, max xy) on P.
vec4 proj4(vec3 lsPoint) {
  float scale = r4d.plane.x / lsPoint.z;
  vec2 centre = lsPoint.xy * scale;
  vec2 half_ = r4d.light.xy * abs(scale - 1.0);
  return vec4(centre - half_, centre + half_);
}

// Algorithm 2: the projection from the corner sample L0 = (-a, -b, 0) onto P (for d <= D
// this is the max corner of Proj4).
vec2 projFromL0(vec3 lsPoint) {
  float scale = r4d.plane.x / lsPoint.z;
  return lsPoint.xy * scale - r4d.light.xy * (1.0 - scale);
}

// FB pixel (column, row) holding a P-space point, unclamped.
ivec2 fbPixel(vec2 pPoint) { return ivec2(floor((pPoint - r4d.fb.xy) * r4d.fb.zw)); }

// FB pixels a P-space box covers, clamped to the FB: (min col, min row, max col, max row);
// empty when max < min.
ivec4 fbPixelRange(vec4 pBox) {
  ivec2 lo = max(fbPixel(pBox.xy), ivec2(0));
  ivec2 hi = min(fbPixel(pBox.zw), r4d.sizes.xy - 1);
  return ivec4(lo, hi);
}

// §3.3 row masks. A plane's value at light sample (i, j) is g = A_i + j S, with A_i the
// value at the row's first sample and S the step per column. Every test (row or per-sample)
// evaluates exactly this expression, `precise` so the compiler cannot fuse it differently
// in different places: the row masks then equal the per-sample tests bit for bit.
bool planeInside(float rowStart, float step, int column, bool strict) {
  precise float g = rowStart + float(column) * step;
  return strict ? g > 0.0 : g >= 0.0;
}

// The first k columns as a bit set (k in [0, 64]; (1u << 32) is undefined, so k = 32 and
// k = 64 are whole words).
uvec2 prefixBits(int k) {
  uint lo = k >= 32 ? 0xffffffffu : (1u << uint(max(k, 0))) - 1u;
  uint hi = k >= 64 ? 0xffffffffu : (k > 32 ? (1u << uint(k - 32)) - 1u : 0u);
  return uvec2(lo, hi);
}

// The columns j in [0, m) where the plane is inside (Algorithm 3 lines 12-16): g is monotone
// in j, so they are a prefix or a suffix; the split column k comes from the intersection of
// the row with the plane (k = -A/S) and is then checked against the samples on either side,
// so round-off in the division cannot move a bit (it is far below one column: two checked
// steps each way are plenty). No loops here: a driver may stop a shader after a fixed number
// of loop iterations in all (65535 on Mesa's CPU drivers), so the passes bound their loops.
uvec2 rowInside(float rowStart, float step, int m, bool strict) {
  if (step == 0.0) return planeInside(rowStart, step, 0, strict) ? prefixBits(m) : uvec2(0u);
  float crossing = clamp(-rowStart / step, -1.0, float(m) + 1.0);
  if (step > 0.0) {  // inside from column k on
    int k = clamp(int(ceil(crossing)), 0, m);
    if (k > 0 && planeInside(rowStart, step, k - 1, strict)) --k;
    if (k > 0 && planeInside(rowStart, step, k - 1, strict)) --k;
    if (k < m && !planeInside(rowStart, step, k, strict)) ++k;
    if (k < m && !planeInside(rowStart, step, k, strict)) ++k;
    return prefixBits(m) & ~prefixBits(k);
  }
  int k = clamp(int(floor(crossing)) + 1, 0, m);  // inside up to column k - 1
  if (k < m && planeInside(rowStart, step, k, strict)) ++k;
  if (k < m && planeInside(rowStart, step, k, strict)) ++k;
  if (k > 0 && !planeInside(rowStart, step, k - 1, strict)) --k;
  if (k > 0 && !planeInside(rowStart, step, k - 1, strict)) --k;
  return prefixBits(k);
}

// A plane as its value at sample (0, 0), per row and per column: g_ij = c + i rowStep + j step.
struct LightPlane {
  float c, rowStep, step;
  bool strict;
};

// The plane through lsOrigin with normal n, oriented by sign (inside: sign * value >= 0).
LightPlane lightPlane(vec3 n, vec3 lsOrigin, float sign, bool strict) {
  n *= sign;
  LightPlane plane;
  plane.c = -n.x * r4d.light.x - n.y * r4d.light.y - dot(n, lsOrigin);
  plane.rowStep = n.y * r4d.light.w;
  plane.step = n.x * r4d.light.z;
  plane.strict = strict;
  return plane;
}

float rowStart(LightPlane plane, int row) {
  precise float start = plane.c + float(row) * plane.rowStep;
  return start;
}

// 1D passes over a list: 64 invocations per group, groups laid out in 2D (a dimension holds
// at most 65535 groups); app side: Raster4dGpu::dispatchLinear.
uint linearIndex() {
  return gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * 64u;
}

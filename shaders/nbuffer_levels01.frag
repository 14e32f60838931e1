// N-buffer levels 0 and 1 in one pass (thesis §3.5, layout in shared/nbuffer.glsl), straight
// from the light layers. Level 0 is a copy of them, (zNearMin, zNearMax, zFarMax) =
// (near, near, far) over a 1x1 window; level 1 the min/max over the 2x2 window, read here as
// four near and four far texels instead of four RGBA32F level-0 texels in a pass of its own
// (issue 14: the level-1 pass cost about 2 ms of the N-buffer's 15 at 512^2). This texel is
// one of the window's four, so its level-0 value comes from the same reads. A fragment
// shader writing two layers of the array (app/gl/screen_triangle.h: why not a compute pass);
// where the map has one level, only output 0 has a draw buffer and output 1 is dropped.
#include "shared/nbuffer.glsl"
#include "shared/nbuffer_layout.h"
layout(binding = NBUFFER_NEAR_UNIT) uniform sampler2D nearLayer;
layout(binding = NBUFFER_FAR_UNIT) uniform sampler2D farLayer;
layout(location = 0) out vec4 level0;
layout(location = 1) out vec4 level1;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  ivec2 size = textureSize(nearLayer, 0);
  // 1. The level-1 window [lo, hi] per axis (lo == hi on an axis one texel wide).
  ivec2 rangeX = nbufferWindow1D(1, texel.x, size.x), rangeY = nbufferWindow1D(1, texel.y, size.y);
  ivec2 lo = ivec2(rangeX.x, rangeY.x), hi = ivec2(rangeX.y, rangeY.y);
  // 2. Its four texels in both layers.
  vec4 near = vec4(texelFetch(nearLayer, lo, 0).r, texelFetch(nearLayer, ivec2(hi.x, lo.y), 0).r,
                   texelFetch(nearLayer, ivec2(lo.x, hi.y), 0).r, texelFetch(nearLayer, hi, 0).r);
  vec4 far = vec4(texelFetch(farLayer, lo, 0).r, texelFetch(farLayer, ivec2(hi.x, lo.y), 0).r,
                  texelFetch(farLayer, ivec2(lo.x, hi.y), 0).r, texelFetch(farLayer, hi, 0).r);
  // 3. Level 0: this texel is lo or hi on each axis (selects, not a variable index: llvmpipe
  //    would index lane by lane).
  bvec2 atHi = equal(texel, hi);
  vec2 nearFar = atHi.y ? (atHi.x ? vec2(near.w, far.w) : vec2(near.z, far.z))
                        : (atHi.x ? vec2(near.y, far.y) : vec2(near.x, far.x));
  level0 = vec4(nearFar.x, nearFar.x, nearFar.y, 0.0);
  // 4. Level 1.
  level1 = vec4(min(min(near.x, near.y), min(near.z, near.w)),
                max(max(near.x, near.y), max(near.z, near.w)),
                max(max(far.x, far.y), max(far.z, far.w)), 0.0);
}

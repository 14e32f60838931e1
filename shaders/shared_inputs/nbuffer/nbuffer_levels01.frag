// N-buffer levels 0 and 1 in one pass (thesis §3.5, layout in shared/nbuffer.glsl), straight
// from the light layers. Level 0 is a copy of them, (zNearMin, zNearMax, zFarMax) =
// (near, near, far) over a 1x1 window; level 1 the min/max over the 2x2 window, read here as
// four near and four far texels instead of four RGBA32F level-0 texels in a pass of its own
// (which would write level 0 and read it back). This texel is
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
  // 1. The level-1 window's first texel per axis, lo; the window is lo and lo + 1 (one texel
  //    on an axis one texel wide).
  ivec2 lo = ivec2(nbufferWindow1D(1, texel.x, size.x).x, nbufferWindow1D(1, texel.y, size.y).x);
  // 2. Its four texels in each layer, one gather around their common corner lo + 1 (one
  //    fetch of four texels; as in minmax_level.frag). Components:
  //    x (lo.x, lo.y+1), y (lo.x+1, lo.y+1), z (lo.x+1, lo.y), w (lo.x, lo.y); on an axis
  //    one texel wide the texel clamped to the edge (gl_texture.cpp) repeats the one there.
  vec2 corner = vec2(lo + 1) / vec2(size);
  vec4 near = textureGather(nearLayer, corner), far = textureGather(farLayer, corner);
  // 3. Level 0: this texel is one of the four.
  bvec2 second = greaterThan(texel, lo);
  vec2 nearFar = second.y ? (second.x ? vec2(near.y, far.y) : vec2(near.x, far.x))
                          : (second.x ? vec2(near.z, far.z) : vec2(near.w, far.w));
  level0 = vec4(nearFar.x, nearFar.x, nearFar.y, 0.0);
  // 4. Level 1.
  level1 = vec4(min(min(near.x, near.y), min(near.z, near.w)),
                max(max(near.x, near.y), max(near.z, near.w)),
                max(max(far.x, far.y), max(far.z, far.w)), 0.0);
}

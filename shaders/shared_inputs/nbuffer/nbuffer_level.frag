// N-buffer level n from level n-1 (thesis §3.5, Fig 3.6; layout in shared/nbuffer.glsl):
// the level-n window of a texel is tiled by two level-(n-1) windows per axis, so 4 fetches
// give its exact min/max. Windows are centered and shifted inward at the borders.
// A fragment shader writing layer n (app/gl/screen_triangle.h: why not a compute pass);
// layer n-1 of the same texture is read through an image unit, not a texture unit, so this
// is no rendering feedback loop (GL 4.5 §9.3.1 concerns textures bound to texture units).
#include "shared/nbuffer.glsl"
#include "shared/nbuffer_layout.h"
layout(binding = NBUFFER_FINER_IMAGE, rgba32f) uniform readonly image2D finer;  // level n-1
layout(location = NBUFFER_LEVEL_LOCATION) uniform int uLevel;                   // n >= 2
layout(location = 0) out vec4 coarser;                                          // level n

void main() {
  ivec2 size = imageSize(finer);
  ivec2 texel = ivec2(gl_FragCoord.xy);
  ivec2 lo = ivec2(nbufferWindow1D(uLevel, texel.x, size.x).x,
                   nbufferWindow1D(uLevel, texel.y, size.y).x);
  // The level-(n-1) windows starting at lo and lo + 2^(n-1) tile this one (where the map is
  // narrower than 2^n, both are shifted inward and still cover it), read at the texels that
  // hold them: the distinct ones, written also when the levels are not shown (nbuffer.glsl).
  int halfSpan = 1 << (uLevel - 1);
  ivec2 first = ivec2(nbufferTexelForWindow(uLevel - 1, lo.x, size.x),
                      nbufferTexelForWindow(uLevel - 1, lo.y, size.y));
  ivec2 second = ivec2(nbufferTexelForWindow(uLevel - 1, lo.x + halfSpan, size.x),
                       nbufferTexelForWindow(uLevel - 1, lo.y + halfSpan, size.y));
  vec4 a = imageLoad(finer, first);
  vec4 b = imageLoad(finer, ivec2(second.x, first.y));
  vec4 c = imageLoad(finer, ivec2(first.x, second.y));
  vec4 d = imageLoad(finer, second);
  coarser = vec4(min(min(a.x, b.x), min(c.x, d.x)), max(max(a.y, b.y), max(c.y, d.y)),
                 max(max(a.z, b.z), max(c.z, d.z)), 0.0);
}

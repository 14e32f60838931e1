// Min-max mipmap level n >= 1 (layout in shared/minmax.glsl): level n takes min/max over
// the (up to) 2 x 2 children in level n-1. Level 1 reads its children from the layers as
// (near, near, far): level 0 is the layers, never stored (storing it would be a full RGBA32F
// copy of them).
// Two programs (MINMAX_FROM_LAYERS 1: level 1; 0: the coarser levels), each reading one
// source.
// A fragment shader drawn over the whole of mip level n - 1 (app/gl/screen_triangle.h: why
// not a compute pass), one texel per invocation; texels past the level's ceil(W / 2^n) x
// ceil(H / 2^n) (the power-of-two padding, minmax.glsl) are written (0, 0, 0, 0). The coarser
// levels read level n-1 through a texture view of its mip level alone while the draw writes
// a view of mip level n - 1 alone: two levels of one texture, neither view reaching the other's
// level, so no rendering feedback loop (GL 4.5 §9.3.1).
#include "shared/minmax.glsl"
#include "stages/shared_inputs/minmax/minmax_layout.h"
layout(binding = MINMAX_NEAR_UNIT) uniform sampler2D nearLayer;
layout(binding = MINMAX_FAR_UNIT) uniform sampler2D farLayer;
layout(binding = MINMAX_FINER_UNIT) uniform sampler2D finerLevel;
layout(location = MINMAX_LEVEL_LOCATION) uniform int uLevel;
layout(location = MINMAX_SIZE_LOCATION) uniform ivec2 uSize;
layout(location = 0) out vec4 bounds;

#if !defined(MINMAX_FROM_LAYERS)
#error "minmax_level.frag needs MINMAX_FROM_LAYERS 0 or 1 (stages/shared_inputs/minmax/minmax_build.h)"
#endif

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  ivec2 levelSize = ivec2(minmaxLevelSize(uLevel, uSize.x), minmaxLevelSize(uLevel, uSize.y));
  if (any(greaterThanEqual(texel, levelSize))) {  // padding: no cell of the hierarchy
    bounds = vec4(0.0);
    return;
  }
#if MINMAX_FROM_LAYERS
  // Level 1: the 2 x 2 children from the layers as (near, near, far), each layer in one
  // gather around the children's common corner 2 * texel + 1 (one fetch of four texels);
  // past an odd map's last row or column the texel clamped to the
  // edge (gl_texture.cpp) repeats a child, which leaves minimum and maximum unchanged.
  vec2 corner = vec2(2 * texel + 1) / vec2(uSize);
  vec4 nearDepths = textureGather(nearLayer, corner), farDepths = textureGather(farLayer, corner);
  bounds = vec4(min(min(nearDepths.x, nearDepths.y), min(nearDepths.z, nearDepths.w)),
                max(max(nearDepths.x, nearDepths.y), max(nearDepths.z, nearDepths.w)),
                max(max(farDepths.x, farDepths.y), max(farDepths.z, farDepths.w)), 0.0);
#else
  ivec2 finerSize =
      ivec2(minmaxLevelSize(uLevel - 1, uSize.x), minmaxLevelSize(uLevel - 1, uSize.y));
  // The first child always exists; the others where the finer level reaches them (past it
  // lies the padding, never read).
  bounds = texelFetch(finerLevel, 2 * texel, 0);
  for (int child = 1; child < 4; ++child) {
    ivec2 finer = 2 * texel + ivec2(child & 1, child >> 1);
    if (any(greaterThanEqual(finer, finerSize))) continue;
    vec4 b = texelFetch(finerLevel, finer, 0);
    bounds = vec4(min(bounds.x, b.x), max(bounds.y, b.y), max(bounds.z, b.z), 0.0);
  }
#endif
}

// Min-max mipmap level n >= 1 (layout in shared/minmax.glsl): level n takes min/max over
// the (up to) 2 x 2 children in level n-1. Level 1 reads its children from the layers as
// (near, near, far): level 0 is the layers, never stored (storing it would be a full RGBA32F
// copy of them).
// Two programs (MINMAX_FROM_LAYERS 1: level 1; 0: the coarser levels), each reading one
// source.
// A fragment shader drawn over the level's rectangle of the atlas (app/gl/screen_triangle.h:
// why not a compute pass); the coarser levels read level n-1 of the same atlas through an
// image unit, a rectangle this draw does not write (no rendering feedback loop: GL 4.5
// §9.3.1 concerns textures bound to texture units).
#include "shared/minmax.glsl"
#include "shared/minmax_layout.h"
layout(binding = MINMAX_NEAR_UNIT) uniform sampler2D nearLayer;
layout(binding = MINMAX_FAR_UNIT) uniform sampler2D farLayer;
layout(binding = MINMAX_ATLAS_IMAGE, rgba32f) uniform readonly image2D atlas;
layout(location = MINMAX_LEVEL_LOCATION) uniform int uLevel;
layout(location = MINMAX_SIZE_LOCATION) uniform ivec2 uSize;
layout(location = 0) out vec4 bounds;

#if !defined(MINMAX_FROM_LAYERS)
#error "minmax_level.frag needs MINMAX_FROM_LAYERS 0 or 1 (app/gl/minmax_build.h)"
#endif

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy) - minmaxLevelOrigin(uLevel, uSize);
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
  ivec2 finerOrigin = minmaxLevelOrigin(uLevel - 1, uSize);
  // The first child always exists; the others where the finer level reaches them.
  bounds = imageLoad(atlas, finerOrigin + 2 * texel);
  for (int child = 1; child < 4; ++child) {
    ivec2 finer = 2 * texel + ivec2(child & 1, child >> 1);
    if (any(greaterThanEqual(finer, finerSize))) continue;
    vec4 b = imageLoad(atlas, finerOrigin + finer);
    bounds = vec4(min(bounds.x, b.x), max(bounds.y, b.y), max(bounds.z, b.z), 0.0);
  }
#endif
}

// Min-max mipmap level n >= 1 (layout in shared/minmax.glsl): level n takes min/max over
// the (up to) 2 x 2 children in level n-1. Level 1 reads its children from the layers as
// (near, near, far): level 0 is the layers, never stored (issue 14: storing it was a full
// RGBA32F copy, half the build).
#include "shared/minmax.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
#include "shared/minmax_layout.h"
layout(binding = MINMAX_NEAR_UNIT) uniform sampler2D nearLayer;
layout(binding = MINMAX_FAR_UNIT) uniform sampler2D farLayer;
layout(binding = MINMAX_ATLAS_IMAGE, rgba32f) uniform coherent image2D atlas;
layout(location = MINMAX_LEVEL_LOCATION) uniform int uLevel;
layout(location = MINMAX_SIZE_LOCATION) uniform ivec2 uSize;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 levelSize = ivec2(minmaxLevelSize(uLevel, uSize.x), minmaxLevelSize(uLevel, uSize.y));
  if (any(greaterThanEqual(texel, levelSize))) return;
  vec4 bounds;
  if (uLevel == 1) {
    for (int child = 0; child < 4; ++child) {
      ivec2 finer = 2 * texel + ivec2(child & 1, child >> 1);
      if (any(greaterThanEqual(finer, uSize))) continue;  // the first child always exists
      float nearDepth = texelFetch(nearLayer, finer, 0).r, farDepth = texelFetch(farLayer, finer, 0).r;
      vec4 b = vec4(nearDepth, nearDepth, farDepth, 0.0);
      bounds = child == 0 ? b : vec4(min(bounds.x, b.x), max(bounds.y, b.y), max(bounds.z, b.z), 0.0);
    }
  } else {
    ivec2 finerSize = ivec2(minmaxLevelSize(uLevel - 1, uSize.x), minmaxLevelSize(uLevel - 1, uSize.y));
    ivec2 finerOrigin = minmaxLevelOrigin(uLevel - 1, uSize);
    // 1. The first child always exists; the others where the finer level reaches them.
    bounds = imageLoad(atlas, finerOrigin + 2 * texel);
    for (int child = 1; child < 4; ++child) {
      ivec2 finer = 2 * texel + ivec2(child & 1, child >> 1);
      if (any(greaterThanEqual(finer, finerSize))) continue;
      vec4 b = imageLoad(atlas, finerOrigin + finer);
      bounds = vec4(min(bounds.x, b.x), max(bounds.y, b.y), max(bounds.z, b.z), 0.0);
    }
  }
  imageStore(atlas, minmaxLevelOrigin(uLevel, uSize) + texel, bounds);
}

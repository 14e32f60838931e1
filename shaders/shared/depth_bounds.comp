// Min and max over the texels of a depth map that hold a surface (shared/ssm_layout.h
// DepthBounds): soft shadow maps size their quads with the farthest receiver, PCSS sizes
// its blocker search with the nearest occluder.
#include "shared/ssm_layout.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = DEPTH_BOUNDS_MAP_UNIT) uniform sampler2D depthMap;
layout(std430, binding = DEPTH_BOUNDS_BINDING) buffer Bounds { DepthBounds bounds; };
layout(location = DEPTH_BOUNDS_EMPTY_LOCATION) uniform float uEmpty;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, textureSize(depthMap, 0)))) return;
  float lsDepth = texelFetch(depthMap, texel, 0).r;
  if (lsDepth == uEmpty) return;
  uint bits = floatBitsToUint(max(lsDepth, 0.0));
  atomicMin(bounds.minBits, bits);
  atomicMax(bounds.maxBits, bits);
  atomicAdd(bounds.count, 1u);
}

// N-buffer level 0 (thesis §3.5, layout in shared/nbuffer.glsl): a copy of the light
// layers, (zNearMin, zNearMax, zFarMax) = (near, near, far) over a 1x1 window.
layout(local_size_x = 8, local_size_y = 8) in;
#include "shared/nbuffer_layout.h"
layout(binding = NBUFFER_NEAR_UNIT) uniform sampler2D nearLayer;
layout(binding = NBUFFER_FAR_UNIT) uniform sampler2D farLayer;
layout(binding = NBUFFER_COARSER_IMAGE, rgba32f) uniform writeonly image2D level0;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(level0)))) return;
  float nearDepth = texelFetch(nearLayer, texel, 0).r;
  float farDepth = texelFetch(farLayer, texel, 0).r;
  imageStore(level0, texel, vec4(nearDepth, nearDepth, farDepth, 0.0));
}

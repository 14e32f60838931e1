// N-buffer level 0 (thesis §3.5, layout in shared/nbuffer.glsl): a copy of the light
// layers, (zNearMin, zNearMax, zFarMax) = (near, near, far) over a 1x1 window. A fragment
// shader over the level's texels (app/gl/screen_triangle.h: why not a compute pass).
#include "shared/nbuffer_layout.h"
layout(binding = NBUFFER_NEAR_UNIT) uniform sampler2D nearLayer;
layout(binding = NBUFFER_FAR_UNIT) uniform sampler2D farLayer;
layout(location = 0) out vec4 level0;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  float nearDepth = texelFetch(nearLayer, texel, 0).r;
  float farDepth = texelFetch(farLayer, texel, 0).r;
  level0 = vec4(nearDepth, nearDepth, farDepth, 0.0);
}

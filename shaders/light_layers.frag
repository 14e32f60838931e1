// Light depth layers (thesis §3.3): the fragment's linear light depth (frame_block.h) is
// written as its depth, so the depth test picks the nearest (near layer, LESS) or the
// farthest (far layer, GREATER) surface along each light ray.
#define FRAME_BLOCKS_FROM_VERTEX_STAGE  // frame.glsl: why
#include "shared/frame.glsl"
layout(location = 0) in vec3 wsPosition;
void main() {
  vec4 lsPosition = light.lightViewFromWorld * vec4(wsPosition, 1.0);
  gl_FragDepth = clamp(zToLsDepth(-lsPosition.z), 0.0, 1.0);
}

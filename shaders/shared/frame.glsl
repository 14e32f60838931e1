// GLSL side of the per-frame block and the light-space helpers (see frame_block.h).
#include "frame_block.h"
layout(std140, binding = 0) uniform FrameBlock { FrameUniforms frame; };

// Linear light-space depth conversions (encoding documented in frame_block.h).
float zToLsDepth(float z) {
  return (z - frame.lightDepthRange.x) / (frame.lightDepthRange.y - frame.lightDepthRange.x);
}
float lsDepthToZ(float lsDepth) {
  return frame.lightDepthRange.x + lsDepth * (frame.lightDepthRange.y - frame.lightDepthRange.x);
}
// World position -> (u, v in [0,1] over the map, z = distance along the light axis).
vec3 lightMapCoords(vec3 wsPosition) {
  vec4 clip = frame.lightClipFromWorld * vec4(wsPosition, 1.0);
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  return vec3(uv, clip.w);  // perspective w is the view-space distance along the axis
}

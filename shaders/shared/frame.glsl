// GLSL side of the per-frame camera block, the light block and the light-space helpers
// (see frame_block.h and light_block.h).
#include "frame_block.h"
#include "light_block.h"
// Read where they are used: every stage binds them once for the whole pass.
layout(std140, binding = FRAME_BLOCK_BINDING) uniform FrameBlock { FrameUniforms frame; };
layout(std140, binding = LIGHT_BLOCK_BINDING) uniform LightBlock { LightUniforms light; };

// Linear light-space depth conversions (encoding documented in light_block.h).
float zToLsDepth(float z) {
  return (z - light.lightDepthRange.x) / (light.lightDepthRange.y - light.lightDepthRange.x);
}
float lsDepthToZ(float lsDepth) {
  return light.lightDepthRange.x + lsDepth * (light.lightDepthRange.y - light.lightDepthRange.x);
}
// World position -> (u, v in [0,1] over the map, z = distance along the light axis).
vec3 lightMapCoords(vec3 wsPosition) {
  vec4 clip = light.lightClipFromWorld * vec4(wsPosition, 1.0);
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  return vec3(uv, clip.w);  // perspective w is the view-space distance along the axis
}

// GLSL side of the per-frame camera block, the light block and the light-space helpers
// (see frame_block.h and light_block.h).
#include "frame_block.h"
#include "light_block.h"
// Where a fragment shader reads the blocks from when its vertex shader hands them over
// (screen_triangle.vert, scene.vert): flat outputs at these locations, after the two that
// scene.vert interpolates (29 of the 32 vec4 inputs GL 4.5 guarantees a fragment shader).
#define FRAME_BLOCKS_LIGHT_LOCATION 2   // LightUniforms: 16 locations
#define FRAME_BLOCKS_FRAME_LOCATION 18  // FrameUniforms: 11 locations
#if defined(FRAME_BLOCKS_FROM_VERTEX_STAGE)
// Flat inputs, not uniform blocks (issue 14, bench/llvmpipe-uniforms): llvmpipe reads a
// uniform in a fragment shader lane by lane, a gather per scalar (about 0.1 ms per scalar
// per 640x480 image, again on every loop iteration), while a flat input is set up once per
// triangle. A fragment shader defines FRAME_BLOCKS_FROM_VERTEX_STAGE before including this
// file where its vertex shader hands the blocks over.
layout(location = FRAME_BLOCKS_LIGHT_LOCATION) flat in LightUniforms light;
layout(location = FRAME_BLOCKS_FRAME_LOCATION) flat in FrameUniforms frame;
#else
layout(std140, binding = FRAME_BLOCK_BINDING) uniform FrameBlock { FrameUniforms frame; };
layout(std140, binding = LIGHT_BLOCK_BINDING) uniform LightBlock { LightUniforms light; };
#endif

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

// GLSL side of the per-frame camera block, the light block and the light-space helpers
// (see frame_block.h and light_block.h).
#include "frame_block.h"
#include "light_block.h"
// Three ways to read the blocks (issue 14, measured in bench/llvmpipe-uniforms): llvmpipe
// reads a uniform block lane by lane, a gather per scalar, in every fragment shader and
// inside any branch or loop of a compute shader (about 0.1 ms per scalar per 640x480 image,
// again on every loop iteration), and with one load per scalar at the top of a compute
// shader's main(), before any branch.
//  1. FRAME_BLOCKS_FROM_VERTEX_STAGE: flat inputs that the vertex shader (screen_triangle.vert,
//     scene.vert) copies from the blocks, set up once per triangle: fragment shaders
//     (classification 0.76, composite 0.72);
//  2. UNIFORM_BLOCKS_LOADED_AT_START: copies that main() fills first thing (loadFrameBlocks;
//     the trace block likewise, trace_ray.glsl): compute shaders whose work runs in loops
//     (trace 0.90, filter 0.89, PCSS 0.77). Member by member: the compiler forwards a
//     whole-struct copy to block reads at each use;
//  3. otherwise the blocks themselves.
// The flat outputs' locations, after the two that scene.vert interpolates (29 of the 32 vec4
// inputs GL 4.5 guarantees a fragment shader):
#define FRAME_BLOCKS_LIGHT_LOCATION 2   // LightUniforms: 16 locations
#define FRAME_BLOCKS_FRAME_LOCATION 18  // FrameUniforms: 11 locations
#if defined(FRAME_BLOCKS_FROM_VERTEX_STAGE)
layout(location = FRAME_BLOCKS_LIGHT_LOCATION) flat in LightUniforms light;
layout(location = FRAME_BLOCKS_FRAME_LOCATION) flat in FrameUniforms frame;
#elif defined(UNIFORM_BLOCKS_LOADED_AT_START)
layout(std140, binding = FRAME_BLOCK_BINDING) uniform FrameBlock { FrameUniforms frameBlock; };
layout(std140, binding = LIGHT_BLOCK_BINDING) uniform LightBlock { LightUniforms lightBlock; };
FrameUniforms frame;
LightUniforms light;
void loadFrameBlocks() {
  frame = FrameUniforms(frameBlock.clipFromWorld, frameBlock.worldFromClip,
                        frameBlock.wsEyePosition, frameBlock.sizes, frameBlock.keys);
  light = LightUniforms(lightBlock.lightClipFromWorld, lightBlock.lightViewFromWorld,
                        lightBlock.wsLightCenter, lightBlock.wsLightRight, lightBlock.wsLightUp,
                        lightBlock.wsLightForward, lightBlock.lightDepthRange, lightBlock.mapSize,
                        lightBlock.bias, lightBlock.sampling);
}
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

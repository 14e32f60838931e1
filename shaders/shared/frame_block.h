// Per-frame camera uniforms, read by C++ (app/gl/gpu_layout.h) and GLSL
// (#include "shared/frame.glsl"). std140: only 16-byte members (vec4, uvec4, mat4) so C++ and
// GLSL offsets agree trivially; app/gl/gpu_layout.h checks every offset with static_assert.
// Bound at FRAME_BLOCK_BINDING for the whole run. The light has its own block
// (light_block.h), written by the `light` stage.
#define FRAME_BLOCK_BINDING 0

struct FrameUniforms {
  mat4 clipFromWorld;       // eye camera
  mat4 worldFromClip;
  vec4 wsEyePosition;       // xyz, w = 1
  uvec4 sizes;              // x, y = eye image; zw unused
  uvec4 keys;               // x = frame key (scrambles the hash per frame), yzw unused
};

// The std140/std430 blocks of shaders/shared/, seen from C++ with glm types, and checked.
#pragma once
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

namespace gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using ivec4 = glm::ivec4;
using mat4 = glm::mat4;
using uint = std::uint32_t;
#include "shared/frame_block.h"
}  // namespace gpu

// std140: mat4 = 64 bytes, vec4 = 16; every member starts on a 16-byte boundary.
static_assert(sizeof(gpu::vec4) == 16 && sizeof(gpu::mat4) == 64 && sizeof(gpu::uvec4) == 16);
static_assert(offsetof(gpu::FrameUniforms, clipFromWorld) == 0);
static_assert(offsetof(gpu::FrameUniforms, worldFromClip) == 64);
static_assert(offsetof(gpu::FrameUniforms, lightClipFromWorld) == 128);
static_assert(offsetof(gpu::FrameUniforms, lightViewFromWorld) == 192);
static_assert(offsetof(gpu::FrameUniforms, wsEyePosition) == 256);
static_assert(offsetof(gpu::FrameUniforms, wsLightCenter) == 272);
static_assert(offsetof(gpu::FrameUniforms, wsLightRight) == 288);
static_assert(offsetof(gpu::FrameUniforms, wsLightUp) == 304);
static_assert(offsetof(gpu::FrameUniforms, wsLightForward) == 320);
static_assert(offsetof(gpu::FrameUniforms, lightDepthRange) == 336);
static_assert(offsetof(gpu::FrameUniforms, sizes) == 352);
static_assert(offsetof(gpu::FrameUniforms, shading) == 368);
static_assert(offsetof(gpu::FrameUniforms, keys) == 384);
static_assert(sizeof(gpu::FrameUniforms) == 400);

// Uniform and storage binding points shared with GLSL.
namespace binding {
constexpr unsigned kFrameUniforms = 0;
}

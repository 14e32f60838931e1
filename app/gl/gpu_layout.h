// The std140/std430 blocks of shaders/shared/, seen from C++ with glm types, and checked.
#pragma once
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <initializer_list>

namespace gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using ivec4 = glm::ivec4;
using mat4 = glm::mat4;
using uint = std::uint32_t;
#include "shared/frame_block.h"
#include "shared/light_block.h"
}  // namespace gpu

// std140: mat4 = 64 bytes, vec4 = 16; every member starts on a 16-byte boundary.
static_assert(sizeof(gpu::vec4) == 16 && sizeof(gpu::mat4) == 64 && sizeof(gpu::uvec4) == 16);
static_assert(offsetof(gpu::FrameUniforms, clipFromWorld) == 0);
static_assert(offsetof(gpu::FrameUniforms, worldFromClip) == 64);
static_assert(offsetof(gpu::FrameUniforms, wsEyePosition) == 128);
static_assert(offsetof(gpu::FrameUniforms, sizes) == 144);
static_assert(offsetof(gpu::FrameUniforms, keys) == 160);
static_assert(sizeof(gpu::FrameUniforms) == 176);

static_assert(offsetof(gpu::LightUniforms, lightClipFromWorld) == 0);
static_assert(offsetof(gpu::LightUniforms, lightViewFromWorld) == 64);
static_assert(offsetof(gpu::LightUniforms, wsLightCenter) == 128);
static_assert(offsetof(gpu::LightUniforms, wsLightRight) == 144);
static_assert(offsetof(gpu::LightUniforms, wsLightUp) == 160);
static_assert(offsetof(gpu::LightUniforms, wsLightForward) == 176);
static_assert(offsetof(gpu::LightUniforms, lightDepthRange) == 192);
static_assert(offsetof(gpu::LightUniforms, mapSize) == 208);
static_assert(offsetof(gpu::LightUniforms, bias) == 224);
static_assert(offsetof(gpu::LightUniforms, sampling) == 240);
static_assert(sizeof(gpu::LightUniforms) == 256);

namespace gpu {
// Binding numbers a shader may use: GL 4.5's guaranteed minimums (compute and fragment
// stages), so every layout header fits any conforming driver.
constexpr int kTextureUnits = 16, kImageUnits = 8, kStorageBindings = 8, kUniformBindings = 14,
              kUniformLocations = 1024;
// The binding numbers of one kind in one shader: distinct and in [0, limit).
constexpr bool distinctBelow(std::initializer_list<int> values, int limit) {
  for (const int* a = values.begin(); a != values.end(); ++a) {
    if (*a < 0 || *a >= limit) return false;
    for (const int* b = values.begin(); b != a; ++b)
      if (*a == *b) return false;
  }
  return true;
}
}  // namespace gpu
static_assert(gpu::distinctBelow({FRAME_BLOCK_BINDING, LIGHT_BLOCK_BINDING}, gpu::kUniformBindings));
static_assert(!gpu::distinctBelow({1, 2, 1}, 8) && !gpu::distinctBelow({8}, 8));

// Uniform binding points shared with GLSL.
namespace binding {
constexpr unsigned kFrameUniforms = FRAME_BLOCK_BINDING;
constexpr unsigned kLightUniforms = LIGHT_BLOCK_BINDING;
}  // namespace binding

// For stages that declare the `light` input: binds the light stage's uniform block
// (shaders/shared/light_block.h) where the shaders' LightBlock reads it.
#pragma once
#include "core/frame.h"
#include "gl/gpu_layout.h"

inline Input lightInput() {
  return Input::buffer("light", "The light frame (Eq 3.1), map size, Eq 3.2 bias group and "
                                "sample hash (stage `light`).");
}

inline void bindLightInput(const Frame& frame, const Stage& stage) {
  glBindBufferBase(GL_UNIFORM_BUFFER, binding::kLightUniforms,
                   frame.inputBuffer(stage, "light").id());
}

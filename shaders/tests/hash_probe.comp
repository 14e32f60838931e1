// Test-only (tests/stages/test_hash.cpp): toUnitSquare of shared/hash.glsl on chosen bit patterns,
// so the extremes (0, 0xFFFFFFFF) can be checked on the GPU as well as random ones.
#include "shared/hash.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Words { uvec4 words[]; };
layout(std430, binding = 1) writeonly buffer Unit { vec4 unit[]; };
layout(location = 0) uniform uint uCount;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  unit[i] = vec4(toUnitSquare(words[i].xy), toUnitSquare(words[i].zw));
}

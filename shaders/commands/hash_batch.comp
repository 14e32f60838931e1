// The hash functions of shared/hash.glsl over a batch of inputs, one invocation each: the
// engine of `penumbra hash` (app/cli/hash_command.cpp) and of the GPU = C++ tests
// (tests/stages/test_hash.cpp). With HASH_BATCH_LINEAR_SEEDS defined, input i is the seed
// (uFirstSeed + i, 0, 0, 0): thesis §3.1 tests the hash "using the linear sequence
// 1, 2, ..., n as input"; otherwise the seeds are read from a buffer.
#include "shared/hash.glsl"
layout(local_size_x = HASH_BATCH_GROUP_SIZE) in;
#ifndef HASH_BATCH_LINEAR_SEEDS
layout(std430, binding = HASH_BATCH_SEED_BINDING) readonly buffer Seeds { uvec4 seeds[]; };
#endif
layout(std430, binding = HASH_BATCH_OUTPUT_BINDING) writeonly buffer Hashes { uvec4 hashes[]; };
layout(location = 0) uniform uint uCount;
layout(location = 1) uniform uint uKey;
layout(location = 2) uniform int uHashKind;  // HASH_* of shared/hash_kinds.h
layout(location = 3) uniform uint uFirstSeed;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
#ifdef HASH_BATCH_LINEAR_SEEDS
  uvec4 seed = uvec4(uFirstSeed + i, 0u, 0u, 0u);  // wraps modulo 2^32 like the CPU side
#else
  uvec4 seed = seeds[i];
#endif
  hashes[i] = hashRand(seed, uKey, uHashKind);
}

// hash_stats pass 4: the avalanche matrix. Invocation (input bit i, block of 64 inputs):
// for each input of the pattern whose seed.x has bit i clear, set it and count, per bit j of
// word x, how often the output bit flips; an ideal hash flips each with probability 1/2.
#include "hash_patterns.glsl"
layout(local_size_x = HASH_STATS_GROUP_SIZE) in;
layout(std430, binding = HASH_STATS_AVALANCHE_BINDING) buffer Flips { uint flips[]; };
layout(location = HASH_STATS_LOC_COUNT) uniform uint uCount;  // inputs
layout(location = HASH_STATS_LOC_KEY) uniform uint uKey;
layout(location = HASH_STATS_LOC_KIND) uniform int uHashKind;
layout(location = HASH_STATS_LOC_PATTERN) uniform int uPattern;

void main() {
  uint inputBit = gl_GlobalInvocationID.x & 31u;
  uint first = (gl_GlobalInvocationID.x >> 5u) * 64u;
  if (first >= uCount) return;
  uint flipped[32];
  for (int j = 0; j < 32; ++j) flipped[j] = 0u;
  uint inputs = 0u;
  for (uint i = first; i < min(first + 64u, uCount); ++i) {
    uvec4 seed;
    uint key;
    patternInput(uPattern, i, uKey, seed, key);
    if (((seed.x >> inputBit) & 1u) != 0u) continue;  // its pair is counted from the other end
    ++inputs;
    uint change = statsHash(seed, key, uHashKind).x ^
                  statsHash(seed | uvec4(1u << inputBit, 0u, 0u, 0u), key, uHashKind).x;
    for (int j = 0; j < 32; ++j) flipped[j] += (change >> uint(j)) & 1u;
  }
  for (int j = 0; j < 32; ++j)
    if (flipped[j] > 0u) atomicAdd(flips[inputBit * 32u + uint(j)], flipped[j]);
  if (inputs > 0u) atomicAdd(flips[HASH_STATS_FLIPS_INPUTS + inputBit], inputs);
}

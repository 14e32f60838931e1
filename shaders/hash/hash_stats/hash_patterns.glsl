// Input patterns of the hash statistics (Jarzynski & Olano 2020 test every hash on
// several): input number i -> (seed, key) for hashRand. C++ twin in
// tests/support/hash_stats_oracle.cpp.
#include "shared/hash_stats_layout.h"
#include "shared/hash.glsl"

// The even bits of v packed together (Morton decode of one axis).
uint compactEvenBits(uint v) {
  v &= 0x55555555u;
  v = (v | (v >> 1u)) & 0x33333333u;
  v = (v | (v >> 2u)) & 0x0F0F0F0Fu;
  v = (v | (v >> 4u)) & 0x00FF00FFu;
  v = (v | (v >> 8u)) & 0x0000FFFFu;
  return v;
}

void patternInput(int pattern, uint i, uint key, out uvec4 seed, out uint inputKey) {
  inputKey = key;
  if (pattern == HASH_PATTERN_PIXELS) {
    seed = uvec4(i & 1023u, (i >> 10u) & 1023u, i >> 20u, 0u);
  } else if (pattern == HASH_PATTERN_MORTON) {
    seed = uvec4(compactEvenBits(i), compactEvenBits(i >> 1u), 0u, 0u);
  } else if (pattern == HASH_PATTERN_FRAMES) {
    seed = uvec4(0u);
    inputKey = (key << 24u) + i;  // key k: frame keys k 2^24 ...; keys never overlap
  } else {
    seed = uvec4(i + 1u, 0u, 0u, 0u);
  }
}

// hashRand plus the two reference functions of the known-answer tests.
uvec4 statsHash(uvec4 seed, uint key, int kind) {
  if (kind == HASH_STATS_IDENTITY) return seed;
  if (kind == HASH_STATS_CONSTANT) return uvec4(0x5A5A5A5Au);
  return hashRand(seed, key, kind);
}

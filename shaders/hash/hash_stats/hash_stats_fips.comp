// hash_stats pass 3: FIPS 140-2 §4.9.1 counts of one 20,000-bit block per invocation (625
// consecutive x words of a chunk, bits LSB first): ones, 4-bit nibble counts (poker), runs of
// 0s and 1s by length 1..5 and 6+, the longest run, and the number of runs.
#include "shared/hash_stats_layout.h"
layout(local_size_x = HASH_STATS_GROUP_SIZE) in;
layout(std430, binding = HASH_STATS_SAMPLES_BINDING) readonly buffer Samples { uvec4 samples[]; };
layout(std430, binding = HASH_STATS_FIPS_BINDING) writeonly buffer Blocks { uint blocks[]; };
layout(location = HASH_STATS_LOC_COUNT) uniform uint uBlocks;  // whole blocks in this chunk

void main() {
  uint block = gl_GlobalInvocationID.x;
  if (block >= uBlocks) return;
  uint ones = 0u, longest = 0u, totalRuns = 0u;
  uint poker[16], runs[12];
  for (int k = 0; k < 16; ++k) poker[k] = 0u;
  for (int k = 0; k < 12; ++k) runs[k] = 0u;
  uint runBit = 2u, runLength = 0u;  // no run yet
  for (uint w = 0u; w < HASH_STATS_FIPS_WORDS; ++w) {
    uint word = samples[block * HASH_STATS_FIPS_WORDS + w].x;
    ones += uint(bitCount(word));
    for (uint n = 0u; n < 8u; ++n) poker[(word >> (4u * n)) & 15u] += 1u;
    for (uint b = 0u; b < 32u; ++b) {
      uint bit = (word >> b) & 1u;
      if (bit == runBit) {
        ++runLength;
        continue;
      }
      if (runLength > 0u) runs[runBit * 6u + min(runLength, 6u) - 1u] += 1u;
      longest = max(longest, runLength);
      ++totalRuns;
      runBit = bit;
      runLength = 1u;
    }
  }
  runs[runBit * 6u + min(runLength, 6u) - 1u] += 1u;
  longest = max(longest, runLength);
  uint base = block * HASH_STATS_FIPS_STRIDE;
  blocks[base + HASH_STATS_FIPS_ONES] = ones;
  for (int k = 0; k < 16; ++k) blocks[base + HASH_STATS_FIPS_POKER + k] = poker[k];
  for (int k = 0; k < 12; ++k) blocks[base + HASH_STATS_FIPS_RUNS + k] = runs[k];
  blocks[base + HASH_STATS_FIPS_LONGEST] = longest;
  blocks[base + HASH_STATS_FIPS_TOTAL_RUNS] = totalRuns;
}

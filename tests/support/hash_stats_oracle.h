// Independent CPU computation of the hash statistics (docs/hash_stats.md), for the tests: the
// pattern inputs, the samples through the C++ hash twins, and every count, sum and block statistic
// computed directly in double from the numbers, without the GPU's layout or passes.
#pragma once
#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace statsref {

// Input i of a pattern (HASH_PATTERN_*): seed and key.
void patternInput(int pattern, std::uint32_t i, std::uint32_t key, glm::uvec4& seed,
                  std::uint32_t& inputKey);
// hashRand twin plus the identity and constant references (HASH_STATS_IDENTITY/CONSTANT).
glm::uvec4 statsHash(glm::uvec4 seed, std::uint32_t key, int kind);
// Samples (x, y, right-hand x, next-frame x) of inputs 0..count-1.
std::vector<glm::uvec4> samples(int kind, int pattern, std::uint32_t count, std::uint32_t key);

struct Oracle {
  std::vector<std::uint64_t> buckets, pairs, ones;  // 1024, 64 x 64 (row = y), 32
  double chiBuckets = 0, chiPairs = 0, chiBits = 0;
  double rNext = 0, rRight = 0, rFrame = 0;  // Pearson correlations of x / 2^32 (top 24 bits)
  int fipsBlocks = 0, monobitFails = 0, pokerFails = 0, runsFails = 0;
  double runsZ = 0;                            // total runs over all blocks, standardised
  std::vector<std::uint64_t> flips;            // 32 x 32, input bit major
};
// `chunk`: the next-sample pairs do not cross multiples of it (the GPU's chunking).
Oracle compute(const std::vector<glm::uvec4>& samples, std::uint32_t chunk);
// Avalanche counts of the first `inputs` inputs of a pattern: for each input bit i, over the
// inputs whose seed.x has bit i clear, how often each bit of word x flips when it is set
// (32 x 32, input bit major), then those inputs' number per i.
std::vector<std::uint64_t> avalanche(int kind, int pattern, std::uint32_t inputs, std::uint32_t key);

}  // namespace statsref

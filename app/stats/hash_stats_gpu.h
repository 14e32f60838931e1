// The GPU half of the hash statistics (shaders/hash/hash_stats/hash_stats_*.comp): generates the samples of
// a hash over an input pattern in chunks, reduces them to counts and partial sums, and adds
// the partials in double; hashstats::analyze does the rest. Needs a current GL context.
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "gl/gl_texture.h"
#include "gl/shader_program.h"
#include "stats/hash_stats.h"

class GpuHashStats {
public:
  static constexpr std::uint64_t kMaxSamples = 1u << 24;

  // `count` samples of input pattern `pattern` (HASH_PATTERN_*) hashed by `kind` (HASH_* or
  // HASH_STATS_IDENTITY / HASH_STATS_CONSTANT) under `key`; avalanche over the first
  // min(count, HASH_STATS_AVALANCHE_INPUTS) inputs.
  hashstats::Raw run(int kind, int pattern, std::uint64_t count, std::uint32_t key);
  // The same reduction over samples made elsewhere (x, y, right-hand x, next-frame x), e.g.
  // a CPU generator's stream: everything but the avalanche, which needs a function.
  hashstats::Raw runUploaded(const std::vector<glm::uvec4>& samples);
  // Hashes per second: one generate pass over `count` linear inputs computing only the hash,
  // timed with glFinish + steady clock (GL_TIME_ELAPSED is wrong on llvmpipe); best of
  // `repeats`.
  double hashesPerSecond(int kind, std::uint32_t count, int repeats = 3);

  // K keys (key, key + 1, ...), each analysed, and the KS test of each test's K p-values.
  hashstats::KeyedResult runKeys(int kind, int pattern, std::uint64_t count, int keys,
                                 std::uint32_t key);

private:
  void reduceChunk(std::uint32_t count, std::uint64_t fipsBlocksBefore, hashstats::Raw& raw);
  void clearCounts();
  ShaderProgram generate_{{{GL_COMPUTE_SHADER, "hash/hash_stats/hash_stats_generate.comp"}}};
  ShaderProgram throughput_{{{GL_COMPUTE_SHADER, "hash/hash_stats/hash_stats_generate.comp"}},
                            "#define HASH_STATS_THROUGHPUT 1"};
  ShaderProgram accumulate_{{{GL_COMPUTE_SHADER, "hash/hash_stats/hash_stats_accumulate.comp"}}};
  ShaderProgram fips_{{{GL_COMPUTE_SHADER, "hash/hash_stats/hash_stats_fips.comp"}}};
  ShaderProgram avalanche_{{{GL_COMPUTE_SHADER, "hash/hash_stats/hash_stats_avalanche.comp"}}};
  GlBuffer samples_, counts_, sums_, blocks_, flips_;
  bool allocated_ = false;
};

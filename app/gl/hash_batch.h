// Runs the hash functions of shaders/shared/hash.glsl on the GPU over many inputs
// (shaders/commands/hash_batch.comp) and reads the results back with glGetNamedBufferSubData: the
// engine of `penumbra hash` and of the GPU = C++ tests. Needs a current GL context.
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "gl/gl_texture.h"
#include "gl/hash_kind.h"
#include "gl/shader_program.h"

class GpuHashBatch {
public:
  // Inputs per dispatch: 2^20 hashes = 16 MiB of output, 16384 groups (limit: 65535).
  static constexpr std::uint32_t kMaxPerDispatch = 1u << 20;

  // hashes[i] = hashRand((firstSeed + i, 0, 0, 0), key, kind) for i < count (seed wraps
  // modulo 2^32); `hashes` must hold `count` entries.
  void hashLinear(std::uint32_t firstSeed, std::uint32_t count, std::uint32_t key,
                  HashKind kind, glm::uvec4* hashes);
  // hashRand(seeds[i], key, kind) for every i.
  std::vector<glm::uvec4> hash(const std::vector<glm::uvec4>& seeds, std::uint32_t key,
                               HashKind kind);

private:
  void run(ShaderProgram& program, std::uint32_t count, std::uint32_t key, HashKind kind,
           std::uint32_t firstSeed, glm::uvec4* hashes);
  ShaderProgram linear_{{{GL_COMPUTE_SHADER, "commands/hash_batch.comp"}},
                        "#define HASH_BATCH_LINEAR_SEEDS 1"};
  ShaderProgram explicit_{{{GL_COMPUTE_SHADER, "commands/hash_batch.comp"}}};
  GlBuffer seeds_, hashes_;
  size_t seedBytes_ = 0, hashBytes_ = 0;
};

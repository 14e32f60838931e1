#include "gl/hash_batch.h"

#include <algorithm>

// std430 array of uvec4: 16-byte stride, no padding, same as a C++ array of glm::uvec4.
static_assert(sizeof(glm::uvec4) == 16 && alignof(glm::uvec4) <= 16);

namespace {
void ensureSize(const GlBuffer& buffer, size_t& current, size_t bytes, GLenum usage) {
  if (bytes <= current) return;
  clearGlErrors();
  glNamedBufferData(buffer.id(), GLsizeiptr(bytes), nullptr, usage);
  current = 0;
  checkGlAllocation("a hash buffer", bytes);
  current = bytes;
}
}  // namespace

void GpuHashBatch::run(ShaderProgram& program, std::uint32_t count, std::uint32_t key,
                       HashKind kind, std::uint32_t firstSeed, glm::uvec4* hashes) {
  const size_t bytes = size_t(count) * sizeof(glm::uvec4);
  ensureSize(hashes_, hashBytes_, bytes, GL_DYNAMIC_READ);
  program.use();
  glUniform1ui(0, count);
  glUniform1ui(1, key);
  glUniform1i(2, int(kind));
  glUniform1ui(3, firstSeed);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HASH_BATCH_OUTPUT_BINDING, hashes_.id());
  glDispatchCompute((count + HASH_BATCH_GROUP_SIZE - 1) / HASH_BATCH_GROUP_SIZE, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(hashes_.id(), 0, GLsizeiptr(bytes), hashes);
}

void GpuHashBatch::hashLinear(std::uint32_t firstSeed, std::uint32_t count, std::uint32_t key,
                              HashKind kind, glm::uvec4* hashes) {
  for (std::uint32_t done = 0; done < count;) {
    const std::uint32_t chunk = std::min(kMaxPerDispatch, count - done);
    run(linear_, chunk, key, kind, firstSeed + done, hashes + done);
    done += chunk;
  }
}

std::vector<glm::uvec4> GpuHashBatch::hash(const std::vector<glm::uvec4>& seeds,
                                           std::uint32_t key, HashKind kind) {
  std::vector<glm::uvec4> hashes(seeds.size());
  for (size_t done = 0; done < seeds.size();) {
    const auto chunk = std::uint32_t(std::min<size_t>(kMaxPerDispatch, seeds.size() - done));
    const size_t bytes = size_t(chunk) * sizeof(glm::uvec4);
    ensureSize(seeds_, seedBytes_, bytes, GL_DYNAMIC_DRAW);
    glNamedBufferSubData(seeds_.id(), 0, GLsizeiptr(bytes), seeds.data() + done);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HASH_BATCH_SEED_BINDING, seeds_.id());
    run(explicit_, chunk, key, kind, 0, hashes.data() + done);
    done += chunk;
  }
  return hashes;
}

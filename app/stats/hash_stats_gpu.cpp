#include "stats/hash_stats_gpu.h"

#include <algorithm>
#include <chrono>

#include "gl/gpu_layout.h"

// std430 arrays: uvec4 samples (16-byte stride), uint counts and blocks, float sums.
static_assert(sizeof(glm::uvec4) == 16);
static_assert(HASH_STATS_CHUNK % HASH_STATS_FIPS_WORDS == 0, "chunks hold whole FIPS blocks");
static_assert(HASH_STATS_SUM_COUNT <= HASH_STATS_SUM_STRIDE);
static_assert(HASH_STATS_FIPS_TOTAL_RUNS < HASH_STATS_FIPS_STRIDE);
static_assert(HASH_STATS_AVALANCHE_INPUTS % 64 == 0);
static_assert(gpu::distinctBelow({HASH_STATS_SAMPLES_BINDING, HASH_STATS_COUNTS_BINDING,
                                  HASH_STATS_SUMS_BINDING, HASH_STATS_FIPS_BINDING,
                                  HASH_STATS_AVALANCHE_BINDING},
                                 gpu::kStorageBindings));
static_assert(gpu::distinctBelow({HASH_STATS_LOC_COUNT, HASH_STATS_LOC_FIRST, HASH_STATS_LOC_KEY,
                                  HASH_STATS_LOC_KIND, HASH_STATS_LOC_PATTERN},
                                 gpu::kUniformLocations));

namespace {
constexpr std::uint32_t kInvocationsPerChunk =
    (HASH_STATS_CHUNK + HASH_STATS_PER_INVOCATION - 1) / HASH_STATS_PER_INVOCATION;
constexpr std::uint32_t kBlocksPerChunk = HASH_STATS_CHUNK / HASH_STATS_FIPS_WORDS;

GLuint groups(std::uint64_t invocations) {
  return GLuint((invocations + HASH_STATS_GROUP_SIZE - 1) / HASH_STATS_GROUP_SIZE);
}
}  // namespace

void GpuHashStats::clearCounts() {
  if (!allocated_) {
    glNamedBufferData(samples_.id(), GLsizeiptr(HASH_STATS_CHUNK) * 16, nullptr, GL_DYNAMIC_COPY);
    glNamedBufferData(counts_.id(), HASH_STATS_COUNT_TOTAL * 4, nullptr, GL_DYNAMIC_READ);
    glNamedBufferData(sums_.id(), GLsizeiptr(kInvocationsPerChunk) * HASH_STATS_SUM_STRIDE * 4,
                      nullptr, GL_DYNAMIC_READ);
    glNamedBufferData(blocks_.id(), GLsizeiptr(kBlocksPerChunk) * HASH_STATS_FIPS_STRIDE * 4,
                      nullptr, GL_DYNAMIC_READ);
    glNamedBufferData(flips_.id(), HASH_STATS_FLIPS_TOTAL * 4, nullptr, GL_DYNAMIC_READ);
    allocated_ = true;
  }
  const GLuint zero = 0;
  glClearNamedBufferData(counts_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  glClearNamedBufferData(flips_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

// Steps 2-3 for the chunk now in samples_: counts and moments, then the FIPS blocks; the
// invocations' moments are joined here in double, the blocks appended.
void GpuHashStats::reduceChunk(std::uint32_t count, std::uint64_t blocksBefore,
                               hashstats::Raw& raw) {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HASH_STATS_SAMPLES_BINDING, samples_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HASH_STATS_COUNTS_BINDING, counts_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HASH_STATS_SUMS_BINDING, sums_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HASH_STATS_FIPS_BINDING, blocks_.id());
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  const std::uint32_t invocations =
      (count + HASH_STATS_PER_INVOCATION - 1) / HASH_STATS_PER_INVOCATION;
  accumulate_.use();
  glUniform1ui(HASH_STATS_LOC_COUNT, count);
  glDispatchCompute(groups(invocations), 1, 1);
  const std::uint32_t blocks = count / HASH_STATS_FIPS_WORDS;
  if (blocks > 0) {
    fips_.use();
    glUniform1ui(HASH_STATS_LOC_COUNT, blocks);
    glDispatchCompute(groups(blocks), 1, 1);
  }
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);

  std::vector<float> sums(size_t(invocations) * HASH_STATS_SUM_STRIDE);
  glGetNamedBufferSubData(sums_.id(), 0, GLsizeiptr(sums.size() * 4), sums.data());
  for (std::uint32_t i = 0; i < invocations; ++i) {
    const float* s = sums.data() + size_t(i) * HASH_STATS_SUM_STRIDE;
    const double n = s[HASH_STATS_SUM_N];
    const double c = double(s[HASH_STATS_SUM_REF_C]) + s[HASH_STATS_SUM_MEAN_C];
    const double r = double(s[HASH_STATS_SUM_REF_R]) + s[HASH_STATS_SUM_MEAN_R];
    const double f = double(s[HASH_STATS_SUM_REF_F]) + s[HASH_STATS_SUM_MEAN_F];
    const double a = double(s[HASH_STATS_SUM_REF_C]) + s[HASH_STATS_SUM_MEAN_A];
    const double b = double(s[HASH_STATS_SUM_REF_C]) + s[HASH_STATS_SUM_MEAN_B];
    raw.right.join({n, c, r, s[HASH_STATS_SUM_M2_C], s[HASH_STATS_SUM_M2_R], s[HASH_STATS_SUM_CO_CR]});
    raw.frame.join({n, c, f, s[HASH_STATS_SUM_M2_C], s[HASH_STATS_SUM_M2_F], s[HASH_STATS_SUM_CO_CF]});
    raw.next.join({s[HASH_STATS_SUM_NEXT_N], a, b, s[HASH_STATS_SUM_M2_A], s[HASH_STATS_SUM_M2_B],
                   s[HASH_STATS_SUM_CO_AB]});
  }
  raw.fipsBlocks.resize(size_t(blocksBefore + blocks) * HASH_STATS_FIPS_STRIDE);
  if (blocks > 0)
    glGetNamedBufferSubData(blocks_.id(), 0, GLsizeiptr(blocks) * HASH_STATS_FIPS_STRIDE * 4,
                            raw.fipsBlocks.data() + blocksBefore * HASH_STATS_FIPS_STRIDE);
  raw.samples += count;
}

hashstats::Raw GpuHashStats::run(int kind, int pattern, std::uint64_t count, std::uint32_t key) {
  hashstats::Raw raw;
  clearCounts();
  // 1. Generate and reduce chunk by chunk.
  for (std::uint64_t first = 0; first < count; first += HASH_STATS_CHUNK) {
    const auto chunk = std::uint32_t(std::min<std::uint64_t>(HASH_STATS_CHUNK, count - first));
    generate_.use();
    glUniform1ui(HASH_STATS_LOC_COUNT, chunk);
    glUniform1ui(HASH_STATS_LOC_FIRST, std::uint32_t(first));
    glUniform1ui(HASH_STATS_LOC_KEY, key);
    glUniform1i(HASH_STATS_LOC_KIND, kind);
    glUniform1i(HASH_STATS_LOC_PATTERN, pattern);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HASH_STATS_SAMPLES_BINDING, samples_.id());
    glDispatchCompute(groups(chunk), 1, 1);
    reduceChunk(chunk, raw.fipsBlocks.size() / HASH_STATS_FIPS_STRIDE, raw);
  }
  // 2. Avalanche over the first inputs of the pattern: 32 invocations per 64 inputs.
  raw.avalancheInputs = std::uint32_t(std::min<std::uint64_t>(count, HASH_STATS_AVALANCHE_INPUTS));
  avalanche_.use();
  glUniform1ui(HASH_STATS_LOC_COUNT, raw.avalancheInputs);
  glUniform1ui(HASH_STATS_LOC_KEY, key);
  glUniform1i(HASH_STATS_LOC_KIND, kind);
  glUniform1i(HASH_STATS_LOC_PATTERN, pattern);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HASH_STATS_AVALANCHE_BINDING, flips_.id());
  glDispatchCompute(groups((raw.avalancheInputs + 63) / 64 * 32), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(flips_.id(), 0, HASH_STATS_FLIPS_TOTAL * 4, raw.flips.data());
  glGetNamedBufferSubData(counts_.id(), 0, HASH_STATS_COUNT_TOTAL * 4, raw.counts.data());
  return raw;
}

hashstats::Raw GpuHashStats::runUploaded(const std::vector<glm::uvec4>& samples) {
  hashstats::Raw raw;
  clearCounts();
  for (size_t first = 0; first < samples.size(); first += HASH_STATS_CHUNK) {
    const auto chunk = std::uint32_t(std::min<size_t>(HASH_STATS_CHUNK, samples.size() - first));
    glNamedBufferSubData(samples_.id(), 0, GLsizeiptr(chunk) * 16, samples.data() + first);
    reduceChunk(chunk, raw.fipsBlocks.size() / HASH_STATS_FIPS_STRIDE, raw);
  }
  glGetNamedBufferSubData(counts_.id(), 0, HASH_STATS_COUNT_TOTAL * 4, raw.counts.data());
  return raw;
}

double GpuHashStats::hashesPerSecond(int kind, std::uint32_t count, int repeats) {
  clearCounts();
  double best = 1e30;
  for (int r = 0; r < repeats; ++r) {
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    for (std::uint32_t first = 0; first < count; first += HASH_STATS_CHUNK) {
      const std::uint32_t chunk = std::min<std::uint32_t>(HASH_STATS_CHUNK, count - first);
      throughput_.use();
      glUniform1ui(HASH_STATS_LOC_COUNT, chunk);
      glUniform1ui(HASH_STATS_LOC_FIRST, first);
      glUniform1ui(HASH_STATS_LOC_KEY, 0);
      glUniform1i(HASH_STATS_LOC_KIND, kind);
      glUniform1i(HASH_STATS_LOC_PATTERN, HASH_PATTERN_LINEAR);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HASH_STATS_SAMPLES_BINDING, samples_.id());
      glDispatchCompute(groups(chunk), 1, 1);
    }
    glFinish();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return count / best;
}

hashstats::KeyedResult GpuHashStats::runKeys(int kind, int pattern, std::uint64_t count, int keys,
                                             std::uint32_t key) {
  std::vector<hashstats::Result> perKey;
  for (int k = 0; k < keys; ++k) perKey.push_back(hashstats::analyze(run(kind, pattern, count, key + k)));
  return hashstats::combineKeys(std::move(perKey));
}

// hash_stats pass 2: one chunk of samples (generated, or uploaded from the CPU) reduced to
// integer counts (1D buckets, 64 x 64 pairs, ones per bit) and per-invocation float means and
// centred moments for the serial correlations; the CPU joins them in double.
#include "shared/hash_stats_layout.h"
layout(local_size_x = HASH_STATS_GROUP_SIZE) in;
layout(std430, binding = HASH_STATS_SAMPLES_BINDING) readonly buffer Samples { uvec4 samples[]; };
layout(std430, binding = HASH_STATS_COUNTS_BINDING) buffer Counts { uint counts[]; };
layout(std430, binding = HASH_STATS_SUMS_BINDING) writeonly buffer Sums { float sums[]; };
layout(location = HASH_STATS_LOC_COUNT) uniform uint uCount;  // samples in this chunk

float centered(uint word) { return float(word >> 8u) * (1.0 / 16777216.0) - 0.5; }

void main() {
  uint invocation = gl_GlobalInvocationID.x;
  uint first = invocation * HASH_STATS_PER_INVOCATION;
  if (first >= uCount) return;
  uint last = min(first + HASH_STATS_PER_INVOCATION, uCount);
  uint ones[32];
  for (int b = 0; b < 32; ++b) ones[b] = 0u;

  // 1. Counts: 1D bucket of x, 2D cell of (x, y), every set bit of x; sums for the means,
  // taken from the first sample's values (differences of 24-bit fractions are exact).
  uvec4 firstSample = samples[first];
  vec3 ref = vec3(centered(firstSample.x), centered(firstSample.z), centered(firstSample.w));
  vec3 sum = vec3(0.0);   // c, r, f
  vec2 sumNext = vec2(0.0);  // a, b
  float pairs = 0.0;
  for (uint i = first; i < last; ++i) {
    uvec4 sample_ = samples[i];
    atomicAdd(counts[sample_.x >> HASH_STATS_BUCKET_SHIFT], 1u);
    uint cell = (sample_.y >> HASH_STATS_PAIR_SHIFT) * HASH_STATS_PAIR_SIDE +
                (sample_.x >> HASH_STATS_PAIR_SHIFT);
    atomicAdd(counts[HASH_STATS_COUNT_PAIRS + cell], 1u);
    for (int b = 0; b < 32; ++b) ones[b] += (sample_.x >> uint(b)) & 1u;
    sum += vec3(centered(sample_.x), centered(sample_.z), centered(sample_.w)) - ref;
    if (i + 1u < uCount) {
      sumNext += vec2(centered(sample_.x), centered(samples[i + 1u].x)) - ref.x;
      pairs += 1.0;
    }
  }
  for (int b = 0; b < 32; ++b)
    if (ones[b] > 0u) atomicAdd(counts[HASH_STATS_COUNT_BITS + b], ones[b]);

  // 2. Centred second moments: right-hand pixel and next frame against c, and the pairs of
  // consecutive samples.
  float n = float(last - first);
  vec3 mean = sum / n;
  vec2 meanNext = pairs > 0.0 ? sumNext / pairs : vec2(0.0);
  vec3 m2 = vec3(0.0), m2Next = vec3(0.0);  // (cc, rr, ff), (aa, bb, ab)
  vec2 co = vec2(0.0);                     // (cr, cf)
  for (uint i = first; i < last; ++i) {
    uvec4 sample_ = samples[i];
    vec3 d = (vec3(centered(sample_.x), centered(sample_.z), centered(sample_.w)) - ref) - mean;
    m2 += d * d;
    co += d.x * d.yz;
    if (i + 1u < uCount) {
      vec2 e = (vec2(centered(sample_.x), centered(samples[i + 1u].x)) - ref.x) - meanNext;
      m2Next += vec3(e * e, e.x * e.y);
    }
  }
  uint base = invocation * HASH_STATS_SUM_STRIDE;
  sums[base + HASH_STATS_SUM_N] = n;
  sums[base + HASH_STATS_SUM_MEAN_C] = mean.x;
  sums[base + HASH_STATS_SUM_M2_C] = m2.x;
  sums[base + HASH_STATS_SUM_MEAN_R] = mean.y;
  sums[base + HASH_STATS_SUM_M2_R] = m2.y;
  sums[base + HASH_STATS_SUM_CO_CR] = co.x;
  sums[base + HASH_STATS_SUM_MEAN_F] = mean.z;
  sums[base + HASH_STATS_SUM_M2_F] = m2.z;
  sums[base + HASH_STATS_SUM_CO_CF] = co.y;
  sums[base + HASH_STATS_SUM_NEXT_N] = pairs;
  sums[base + HASH_STATS_SUM_MEAN_A] = meanNext.x;
  sums[base + HASH_STATS_SUM_M2_A] = m2Next.x;
  sums[base + HASH_STATS_SUM_MEAN_B] = meanNext.y;
  sums[base + HASH_STATS_SUM_M2_B] = m2Next.y;
  sums[base + HASH_STATS_SUM_CO_AB] = m2Next.z;
  sums[base + HASH_STATS_SUM_REF_C] = ref.x;
  sums[base + HASH_STATS_SUM_REF_R] = ref.y;
  sums[base + HASH_STATS_SUM_REF_F] = ref.z;
}

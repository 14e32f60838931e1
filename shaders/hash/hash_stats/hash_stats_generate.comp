// hash_stats pass 1: the samples of one chunk of a pattern (shared/hash_stats_layout.h): the
// hash of input i, the x word of its right-hand pixel (seed.x + 1) and of the next frame key.
// With HASH_STATS_THROUGHPUT defined it computes only the hash, folds the four words into
// one and writes that (for the hashes-per-second column).
#include "hash_patterns.glsl"
layout(local_size_x = HASH_STATS_GROUP_SIZE) in;
layout(std430, binding = HASH_STATS_SAMPLES_BINDING) writeonly buffer Samples { uvec4 samples[]; };
layout(location = HASH_STATS_LOC_COUNT) uniform uint uCount;  // samples in this chunk
layout(location = HASH_STATS_LOC_FIRST) uniform uint uFirst;  // input number of sample 0
layout(location = HASH_STATS_LOC_KEY) uniform uint uKey;
layout(location = HASH_STATS_LOC_KIND) uniform int uHashKind;
layout(location = HASH_STATS_LOC_PATTERN) uniform int uPattern;

void main() {
  uint local = gl_GlobalInvocationID.x;
  if (local >= uCount) return;
  uvec4 seed;
  uint key;
  patternInput(uPattern, uFirst + local, uKey, seed, key);
  uvec4 h = statsHash(seed, key, uHashKind);
#ifdef HASH_STATS_THROUGHPUT
  samples[local].x = h.x ^ h.y ^ h.z ^ h.w;
#else
  uint right = statsHash(seed + uvec4(1u, 0u, 0u, 0u), key, uHashKind).x;
  uint nextFrame = statsHash(seed, key + 1u, uHashKind).x;
  samples[local] = uvec4(h.x, h.y, right, nextFrame);
#endif
}

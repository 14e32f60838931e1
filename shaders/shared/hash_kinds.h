// The hash functions of the `hash` stage (thesis §3.1, §4.3, Appendix A), numbered once for
// C++ (app/gl/hash_kind.h checks these against its enum with static_assert) and GLSL
// (shared/hash.glsl: hashRand(seed, key, hashKind)). The numbers are also the option index
// of the parameter `light.hash`, so a stage can pass that index straight to the shader.
#define HASH_MD5_16 0     // reduced 16-round MD5, exactly as printed in thesis Appendix A
#define HASH_MD5_64 1     // full 64-round MD5 compression of the same 16-byte message
#define HASH_PCG3D 2      // pcg3d (Jarzynski & Olano 2020), a cheap modern baseline
// Hashes that teach by failing (thesis §3.1: "versions using even fewer rounds ...
// resulted in visible patterns"), and one cheap integer hash in common use:
#define HASH_MD5_4 3      // the first 4 steps of the Appendix A listing
#define HASH_MD5_8 4      // the first 8 steps of the Appendix A listing
#define HASH_LCG15 5      // C rand()-style 15-bit LCG seeded with the pixel index
#define HASH_LCG32 6      // 32-bit LCG (Numerical Recipes) seeded with the pixel index
#define HASH_XXHASH32 7   // xxhash32 of the 4-word seed (Jarzynski & Olano 2020)
#define HASH_KIND_COUNT 8

// shaders/commands/hash_batch.comp: one invocation per input, 64 per group; std430 arrays of uvec4.
#define HASH_BATCH_GROUP_SIZE 64
#define HASH_BATCH_SEED_BINDING 0   // readonly buffer: uvec4 seeds[] (explicit-seed variant)
#define HASH_BATCH_OUTPUT_BINDING 1 // writeonly buffer: uvec4 hashes[]

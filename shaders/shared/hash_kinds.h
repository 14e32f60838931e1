// The hash functions of the `hash` stage (thesis §3.1, §4.3, Appendix A), numbered once for
// C++ (app/gl/hash_kind.h checks these against its enum with static_assert) and GLSL
// (shared/hash.glsl: hashRand(seed, key, hashKind)). The numbers are also the option index
// of the parameter `hash.function`, so a stage can pass that index straight to the shader.
#define HASH_MD5_16 0     // reduced 16-round MD5, exactly as printed in thesis Appendix A
#define HASH_MD5_64 1     // full 64-round MD5 compression of the same 16-byte message
#define HASH_PCG3D 2      // pcg3d (Jarzynski & Olano 2020), a cheap modern baseline
#define HASH_KIND_COUNT 3

// shaders/hash_batch.comp: one invocation per input, 64 per group; std430 arrays of uvec4.
#define HASH_BATCH_GROUP_SIZE 64
#define HASH_BATCH_SEED_BINDING 0   // readonly buffer: uvec4 seeds[] (explicit-seed variant)
#define HASH_BATCH_OUTPUT_BINDING 1 // writeonly buffer: uvec4 hashes[]

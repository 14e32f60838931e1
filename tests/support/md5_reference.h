// CPU twins of shaders/shared/hash.glsl for the tests, written from the sources and not
// from the shader: MD5 from RFC 1321 (checked against the RFC's own test vectors), the
// reduced MD5 from the thesis's Appendix A listing (as a table of its 16 steps), pcg3d and
// xxhash32 from Jarzynski & Olano 2020, the LCGs from ISO C and Numerical Recipes, and the
// [0,1) mapping from its definition.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>

namespace md5ref {

using Digest = std::array<std::uint8_t, 16>;

// MD5 of any byte string (RFC 1321 §3: padding, length, 64 steps per 64-byte block).
Digest md5(const void* data, size_t size);
std::string toHex(const Digest& digest);  // lowercase, as md5sum prints it

// MD5 of the 16 bytes whose little-endian 32-bit words are seed ^ key, its digest read
// back as four little-endian words (the GLSL md5rand64).
glm::uvec4 md5Rand64(glm::uvec4 seed, std::uint32_t key);
// Thesis Appendix A, the reduced 16-round MD5 (the GLSL md5rand16).
glm::uvec4 md5Rand16(glm::uvec4 seed, std::uint32_t key);
// The first `steps` steps of the Appendix A listing (md5Rand16 is steps = 16).
glm::uvec4 md5RandSteps(glm::uvec4 seed, std::uint32_t key, int steps);
// C rand() (the ISO C example) and Numerical Recipes' 32-bit LCG from the pixel index, and
// the 4-word xxhash32 (definitions in shared/hash.glsl).
glm::uvec4 lcg15Rand(glm::uvec4 seed, std::uint32_t key);
glm::uvec4 lcg32Rand(glm::uvec4 seed, std::uint32_t key);
std::uint32_t xxhash32(glm::uvec4 words);
glm::uvec4 xxhash32Rand(glm::uvec4 seed, std::uint32_t key);
// Jarzynski & Olano 2020, and our uvec4 wrapper (definition in shared/hash.glsl).
glm::uvec3 pcg3d(glm::uvec3 v);
glm::uvec4 pcg3dRand(glm::uvec4 seed, std::uint32_t key);
// kind: HASH_* of shared/hash_kinds.h.
glm::uvec4 hashRand(glm::uvec4 seed, std::uint32_t key, int kind);

// (bits >> 8) / 2^24 per component: [0, 1 - 2^-24], exact in float.
glm::vec2 toUnitSquare(glm::uvec2 bits);

}  // namespace md5ref

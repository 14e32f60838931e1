// The hash functions the pipeline can draw its random numbers from (thesis §3.1, §4.3,
// Appendix A), by name. Numbered in shaders/shared/hash_kinds.h for GLSL; checked here.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "shared/hash_kinds.h"

enum class HashKind : int {
  Md5_16 = 0, Md5_64 = 1, Pcg3d = 2, Md5_4 = 3, Md5_8 = 4, Lcg15 = 5, Lcg32 = 6, Xxhash32 = 7
};
static_assert(int(HashKind::Md5_16) == HASH_MD5_16);
static_assert(int(HashKind::Md5_64) == HASH_MD5_64);
static_assert(int(HashKind::Pcg3d) == HASH_PCG3D);
static_assert(int(HashKind::Md5_4) == HASH_MD5_4);
static_assert(int(HashKind::Md5_8) == HASH_MD5_8);
static_assert(int(HashKind::Lcg15) == HASH_LCG15);
static_assert(int(HashKind::Lcg32) == HASH_LCG32);
static_assert(int(HashKind::Xxhash32) == HASH_XXHASH32);

// Indexed by HashKind; also the options of the parameter `light.hash`, whose option
// index is therefore the HashKind (and the GLSL hashKind) itself.
inline constexpr std::array<const char*, HASH_KIND_COUNT> kHashKindNames = {
    "md5_16", "md5_64", "pcg3d", "md5_4", "md5_8", "lcg15", "lcg32", "xxhash32"};

inline std::optional<HashKind> hashKindFromName(const std::string& name) {
  for (size_t i = 0; i < kHashKindNames.size(); ++i)
    if (name == kHashKindNames[i]) return HashKind(int(i));
  return std::nullopt;
}

// The line that compiles a program for one hash alone (shaders/shared/hash.glsl: hashRand),
// for ShaderVariants: `kind` is frame.light.hashKind.
inline std::string hashSpecialization(int kind) {
  return "#define HASH_KIND " + std::to_string(kind) + "\n";
}

// hashSpecialization() of every kind: the variants of a program compiled per hash.
inline std::vector<std::string> hashSpecializations() {
  std::vector<std::string> all;
  for (int kind = 0; kind < HASH_KIND_COUNT; ++kind) all.push_back(hashSpecialization(kind));
  return all;
}

inline std::string hashKindList() {  // "md5_16, md5_64, pcg3d, ..."
  std::string list;
  for (const char* name : kHashKindNames) list += (list.empty() ? "" : ", ") + std::string(name);
  return list;
}

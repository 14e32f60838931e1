// The hash functions the pipeline can draw its random numbers from (thesis §3.1, §4.3,
// Appendix A), by name. Numbered in shaders/shared/hash_kinds.h for GLSL; checked here.
#pragma once
#include <array>
#include <optional>
#include <string>

#include "shared/hash_kinds.h"

enum class HashKind : int { Md5_16 = 0, Md5_64 = 1, Pcg3d = 2 };
static_assert(int(HashKind::Md5_16) == HASH_MD5_16);
static_assert(int(HashKind::Md5_64) == HASH_MD5_64);
static_assert(int(HashKind::Pcg3d) == HASH_PCG3D);

// Indexed by HashKind; also the options of the parameter `light.hash`, whose option
// index is therefore the HashKind (and the GLSL hashKind) itself.
inline constexpr std::array<const char*, HASH_KIND_COUNT> kHashKindNames = {"md5_16", "md5_64",
                                                                            "pcg3d"};

inline std::optional<HashKind> hashKindFromName(const std::string& name) {
  for (size_t i = 0; i < kHashKindNames.size(); ++i)
    if (name == kHashKindNames[i]) return HashKind(int(i));
  return std::nullopt;
}

inline std::string hashKindList() {  // "md5_16, md5_64, pcg3d"
  std::string list;
  for (const char* name : kHashKindNames) list += (list.empty() ? "" : ", ") + std::string(name);
  return list;
}

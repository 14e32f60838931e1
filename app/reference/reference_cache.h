// The reference's disk cache: a reference image costs seconds to minutes, so it is stored
// under a key made from every input that can change it, and reused when the key matches.
//   <cache>/reference/<key>.exr   one channel "visibility", GL order (as the texture)
//   <cache>/reference/<key>.json  what it is (scene, size, m, sampling, seconds) for humans
// <cache> is $PENUMBRA_CACHE, else $XDG_CACHE_HOME/penumbra, else ~/.cache/penumbra.
#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "reference/reference_trace.h"
#include "scene/scene.h"

// 128-bit streaming hash (two independent 64-bit lanes of a multiply-xorshift mix): fast on
// megabytes of G-buffer and collisions need not be considered.
class ContentHash {
public:
  void bytes(const void* data, size_t size);
  template <typename T> void value(const T& v) { bytes(&v, sizeof v); }
  void text(const std::string& s) { value(s.size()); bytes(s.data(), s.size()); }
  std::string hex() const;  // 32 hex digits

private:
  std::uint64_t a_ = 0x243f6a8885a308d3ULL, b_ = 0x13198a2e03707344ULL;
  std::uint64_t length_ = 0;
};

// The key: a version tag of the algorithm, the scene's content (every triangle with its
// receiver-only flag, the light, the camera), the eye size, m, the sampling, the origin offsets, and
// the receivers themselves (the G-buffer positions and normals read back), so a change of
// camera, resolution or driver can never reuse a stale image.
std::string referenceCacheKey(const Scene& scene, const ReferenceRequest& request);

std::filesystem::path referenceCacheDirectory();

// The cached image if it exists and has the request's size; nullopt otherwise (a broken
// file is reported on stderr and treated as absent).
std::optional<std::vector<float>> loadCachedReference(const std::string& key, int width,
                                                      int height);
// Writes atomically (temporary name + rename); failures are reported, not thrown: the cache
// is an optimisation.
void storeCachedReference(const std::string& key, const std::vector<float>& visibility,
                          const ReferenceRequest& request, const std::string& sceneName,
                          double seconds);

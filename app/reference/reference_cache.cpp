#include "reference/reference_cache.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <nlohmann/json.hpp>

#include "io/image_export.h"

namespace {

std::uint64_t mix64(std::uint64_t x) {  // splitmix64 finaliser
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  x ^= x >> 31;
  return x;
}

// Bump when the algorithm changes what a key's image contains.
constexpr const char* kAlgorithmVersion = "penumbra-reference-v1";

}  // namespace

void ContentHash::bytes(const void* data, size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  size_t i = 0;
  for (; i + 8 <= size; i += 8) {
    std::uint64_t word;
    std::memcpy(&word, p + i, 8);
    a_ = mix64(a_ ^ word) + 0x9e3779b97f4a7c15ULL;
    b_ = mix64(b_ + word * 0xff51afd7ed558ccdULL) ^ (b_ >> 17);
  }
  std::uint64_t tail = 0;
  if (size > i) std::memcpy(&tail, p + i, size - i);
  a_ = mix64(a_ ^ tail ^ (std::uint64_t(size - i) << 56));
  b_ = mix64(b_ + tail + 0x632be59bd9b4e019ULL);
  length_ += size;
}

std::string ContentHash::hex() const {
  char text[33];
  std::snprintf(text, sizeof text, "%016llx%016llx",
                (unsigned long long)mix64(a_ ^ length_), (unsigned long long)mix64(b_ + length_));
  return text;
}

std::string referenceCacheKey(const Scene& scene, const ReferenceRequest& request) {
  ContentHash hash;
  hash.text(kAlgorithmVersion);
  for (const SceneObject& object : scene.objects) {
    hash.value(object.receiverOnly);
    hash.value(object.mesh.positions.size());
    hash.bytes(object.mesh.positions.data(), object.mesh.positions.size() * sizeof(glm::vec3));
    hash.value(object.mesh.indices.size());
    hash.bytes(object.mesh.indices.data(), object.mesh.indices.size() * sizeof(std::uint32_t));
  }
  const AreaLight& light = scene.light;
  hash.value(light.center); hash.value(light.forward); hash.value(light.up);
  hash.value(light.width); hash.value(light.height);
  const Camera& camera = scene.camera;
  hash.value(camera.position); hash.value(camera.target); hash.value(camera.up);
  hash.value(camera.fovYDegrees);
  hash.value(request.width); hash.value(request.height);
  hash.value(request.samplesPerSide); hash.value(request.stratified);
  hash.value(request.wsLightCenter); hash.value(request.wsLightRight); hash.value(request.wsLightUp);
  hash.value(request.halfWidth); hash.value(request.halfHeight);
  hash.value(request.relativeEpsilon);
  hash.value(request.minimumEpsilon);
  hash.bytes(request.wsPosition.data(), request.wsPosition.size() * sizeof(float));
  hash.bytes(request.wsNormal.data(), request.wsNormal.size() * sizeof(float));
  return hash.hex();
}

std::filesystem::path referenceCacheDirectory() {
  std::filesystem::path root;
  if (const char* cache = std::getenv("PENUMBRA_CACHE"); cache && *cache) root = cache;
  else if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) root = std::filesystem::path(xdg) / "penumbra";
  else if (const char* home = std::getenv("HOME"); home && *home) root = std::filesystem::path(home) / ".cache" / "penumbra";
  else root = std::filesystem::temp_directory_path() / "penumbra-cache";
  return root / "reference";
}

std::optional<std::vector<float>> loadCachedReference(const std::string& key, int width,
                                                      int height) {
  const auto path = referenceCacheDirectory() / (key + ".exr");
  std::error_code ignored;
  if (!std::filesystem::exists(path, ignored)) return std::nullopt;
  try {
    int w = 0, h = 0;
    std::vector<std::string> channels;
    std::vector<float> values = readExr(path, w, h, channels);
    if (w != width || h != height || channels.size() != 1) {
      std::fprintf(stderr, "reference cache: %s has the wrong shape; recomputing\n", path.c_str());
      return std::nullopt;
    }
    return values;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "reference cache: %s; recomputing\n", error.what());
    return std::nullopt;
  }
}

void storeCachedReference(const std::string& key, const std::vector<float>& visibility,
                          const ReferenceRequest& request, const std::string& sceneName,
                          double seconds) {
  const auto directory = referenceCacheDirectory();
  try {
    std::filesystem::create_directories(directory);
    writeExr(directory / (key + ".exr"), visibility, request.width, request.height, {"visibility"});
    nlohmann::json about = {{"scene", sceneName},
                            {"eye_size", {request.width, request.height}},
                            {"samples_per_side", request.samplesPerSide},
                            {"sampling", request.stratified ? "stratified" : "uniform"},
                            {"relative_epsilon", request.relativeEpsilon}, {"minimum_epsilon", request.minimumEpsilon},
                            {"seconds", seconds}};
    writeTextFile(directory / (key + ".json"), about.dump(2) + "\n");
  } catch (const std::exception& error) {
    std::fprintf(stderr, "reference cache: cannot store %s: %s\n", key.c_str(), error.what());
  }
}

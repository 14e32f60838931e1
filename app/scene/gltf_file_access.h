// File access for tinygltf (the file and its external buffers), as its FsCallbacks: regular
// files only, so a buffer URI naming /dev/zero or a FIFO cannot hang or exhaust memory;
// paths are taken as written (tinygltf's default expands them with wordexp); nothing is
// ever written. The void* is tinygltf's user pointer: a GltfFiles (or nullptr: any regular
// file under kMaxFileBytes).
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

// Files (the glTF and its buffers) of this size or more are refused.
inline constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(1) << 32;

// What a glTF declares it will read, found in its JSON before tinygltf runs: a buffer file
// is read only when its size is the byteLength the glTF declares for it (tinygltf would
// read it whole first and compare after), and only while the scene's budget of bytes read
// (SceneBudget::fileBytes, shared by every file of a scene) lasts. External images are
// never read (penumbra draws no textures).
struct GltfFiles {
  std::vector<std::pair<std::string, std::uint64_t>> buffers;  // decoded URI, byteLength
  std::vector<std::string> images;                             // decoded URIs
  std::uint64_t* remaining = nullptr;                          // the scene's budget
};
// From the glTF's bytes (.gltf JSON or .glb); unreadable JSON gives an empty list (tinygltf
// then reports the problem itself).
GltfFiles declaredFiles(const std::vector<unsigned char>& bytes, bool binary);

bool regularFileExists(const std::string& path, void*);
std::string unexpandedPath(const std::string& path, void*);
bool readRegularFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* files);
bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*);

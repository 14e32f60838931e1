// File access for tinygltf (the file and its external buffers), as its FsCallbacks: regular
// files only, so a buffer URI naming /dev/zero or a FIFO cannot hang or exhaust memory;
// paths are taken as written (tinygltf's default expands them with wordexp); nothing is
// ever written. The void* is tinygltf's user pointer: a GltfFiles (or nullptr: any regular
// file under kMaxFileBytes).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "scene/gltf_declared.h"

// Files (the glTF and its buffers) of this size or more are refused.
inline constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(1) << 32;

// A buffer file is read only when its size is the byteLength the glTF declares for it
// (tinygltf would read it whole first and compare after), and only while the scene's budget
// of bytes read (SceneBudget::fileBytes, shared by every file of a scene) lasts. External
// images are never read (penumbra draws no textures).
struct GltfFiles {
  const GltfDeclared* declared = nullptr;  // the glTF's buffers and images (not null)
  std::uint64_t* remaining = nullptr;      // the scene's budget
};

bool regularFileExists(const std::string& path, void*);
std::string unexpandedPath(const std::string& path, void*);
bool readRegularFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* files);
bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*);

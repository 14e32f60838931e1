// File access for tinygltf (the file and its external buffers), as its FsCallbacks: regular
// files only, so a buffer URI naming /dev/zero or a FIFO cannot hang or exhaust memory;
// paths are taken as written (tinygltf's default expands them with wordexp); nothing is
// ever written. The void* is tinygltf's user pointer (unused).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

// Files (the glTF and its buffers) of this size or more are refused.
inline constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(1) << 32;

bool regularFileExists(const std::string& path, void*);
std::string unexpandedPath(const std::string& path, void*);
bool readRegularFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void*);
bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*);

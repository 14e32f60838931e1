// What a glTF declares, read from its JSON (a .gltf file, or the JSON chunk of a .glb) once,
// before tinygltf runs: the external files it will ask for (so that each is read only at its
// declared size, gltf_file_access.h) and the extensions it requires or uses (so that an
// unsupported geometry extension is named before tinygltf fails on it with a message that
// names neither the extension nor what it does).
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

struct GltfDeclared {
  std::vector<std::pair<std::string, std::uint64_t>> buffers;  // external: decoded URI, byteLength
  std::vector<std::string> images;                             // external: decoded URIs
  std::vector<std::string> extensionsRequired, extensionsUsed;
};

// From the glTF's bytes (.gltf JSON or .glb). JSON that does not parse, or a .glb without a
// JSON chunk, gives an empty declaration: tinygltf then reports the problem itself.
GltfDeclared readGltfDeclared(const std::vector<unsigned char>& bytes, bool binary);

// Extensions that change how geometry is stored; reading past them would produce garbage.
// Returns what the extension does, in words, or nullptr when it is not one of them.
const char* unsupportedGeometryExtension(const std::string& name);
// "<what> (<name>) are not supported".
std::string unsupportedExtensionMessage(const std::string& name, const char* what);

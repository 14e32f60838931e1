#include "scene/gltf_file_access.h"

#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "base/input_error.h"
#include "base/json_input.h"
#include "scene/scene.h"

namespace {

// tinygltf joins "<base dir>/<uri>" (or "./<uri>"): does `path` name `uri`?
bool names(const std::string& path, const std::string& uri) {
  return !uri.empty() && path.size() >= uri.size() &&
         path.compare(path.size() - uri.size(), uri.size(), uri) == 0 &&
         (path.size() == uri.size() || path[path.size() - uri.size() - 1] == '/');
}

std::string bytes(std::uint64_t count) {
  return count >= (std::uint64_t(1) << 20) ? std::to_string(count >> 20) + " MiB"
                                            : std::to_string(count) + " bytes";
}

}  // namespace

// Any existing path: the read below names what is wrong with one that is not a regular file
// (tinygltf would say "File not found" for /dev/zero).
bool regularFileExists(const std::string& path, void*) {
  struct stat info {};
  return ::lstat(path.c_str(), &info) == 0;
}

std::string unexpandedPath(const std::string& path, void*) { return path; }

bool readRegularFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* user) {
  std::error_code error;
  const auto reject = [&](const std::string& why) {
    if (err) *err += "buffer file '" + printable(path, 200) + "': " + why + "\n";
    return false;
  };
  if (std::string problem = regularFileProblem(path); !problem.empty()) return reject(problem);
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error || size >= kMaxFileBytes) return reject("unreadable or 4 GiB or more");
  if (GltfFiles* files = static_cast<GltfFiles*>(user)) {
    const std::pair<std::string, std::uint64_t>* buffer = nullptr;
    for (const auto& declared : files->declared->buffers)
      if (names(path, declared.first)) buffer = &declared;
    if (!buffer) {
      for (const std::string& image : files->declared->images)
        if (names(path, image)) {  // images are skipped: nothing read
          out->assign(1, 0);
          return true;
        }
      return reject("not a buffer the glTF declares");
    }
    if (size != buffer->second)
      return reject("the glTF declares " + std::to_string(buffer->second) + " bytes for it, the file holds " +
                    std::to_string(size) + " (not read)");
    if (files->remaining) {
      if (size > *files->remaining)
        return reject("reading it would pass the scene's limit of " + bytes(kMaxSceneFileBytes) +
                      " of glTF files and buffers in all (not read)");
      *files->remaining -= size;
    }
  }
  std::ifstream in(path, std::ios::binary);
  out->resize(size_t(size));
  if (!in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size)))
    return reject("cannot read it");
  return true;
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "writing is not supported\n";
  return false;
}

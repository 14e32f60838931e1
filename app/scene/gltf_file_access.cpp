#include "scene/gltf_file_access.h"

#include <filesystem>
#include <fstream>

#include "core/input_error.h"

// File access for tinygltf (the file and its external buffers): regular files only, so a
// buffer URI naming /dev/zero or a FIFO cannot hang or exhaust memory; paths are taken as
// written (the default expands them with wordexp); nothing is ever written.
bool regularFileExists(const std::string& path, void*) {
  std::error_code error;
  return std::filesystem::is_regular_file(path, error);
}

std::string unexpandedPath(const std::string& path, void*) { return path; }

bool readRegularFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void*) {
  std::error_code error;
  const auto reject = [&](const std::string& why) {
    if (err) *err += "buffer file '" + printable(path, 200) + "': " + why + "\n";
    return false;
  };
  if (!std::filesystem::is_regular_file(path, error)) return reject("not a regular file");
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error || size >= kMaxFileBytes) return reject("unreadable or 4 GiB or more");
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


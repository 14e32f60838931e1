#include "scene/gltf_file_access.h"

#include <sys/stat.h>

#include <nlohmann/json.hpp>

#include <cctype>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "base/input_error.h"
#include "base/json_input.h"
#include "scene/scene.h"

namespace {

// As tinygltf's dlib::urldecode: "%20" and "+" are spaces.
std::string urlDecoded(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
               std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

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

GltfFiles declaredFiles(const std::vector<unsigned char>& data, bool binary) {
  GltfFiles files;
  std::string text;
  if (binary) {  // header (magic, version, length), then the JSON chunk (length, "JSON")
    if (data.size() < 20 || std::memcmp(data.data() + 16, "JSON", 4) != 0) return files;
    std::uint32_t length = 0;
    std::memcpy(&length, data.data() + 12, 4);
    if (length > data.size() - 20) return files;
    text.assign(reinterpret_cast<const char*>(data.data() + 20), length);
  } else {
    text.assign(reinterpret_cast<const char*>(data.data()), data.size());
  }
  const nlohmann::json root = nlohmann::json::parse(text, nullptr, false);
  if (!root.is_object()) return files;
  const auto external = [](const nlohmann::json& item) {
    return item.is_object() && item.contains("uri") && item["uri"].is_string() &&
           item["uri"].get<std::string>().rfind("data:", 0) != 0;
  };
  if (root.contains("buffers") && root["buffers"].is_array())
    for (const auto& buffer : root["buffers"])
      if (external(buffer)) {
        const auto& length = buffer.contains("byteLength") ? buffer["byteLength"] : nlohmann::json();
        files.buffers.emplace_back(urlDecoded(buffer["uri"].get<std::string>()),
                                   length.is_number_unsigned() ? length.get<std::uint64_t>() : 0);
      }
  if (root.contains("images") && root["images"].is_array())
    for (const auto& image : root["images"])
      if (external(image)) files.images.push_back(urlDecoded(image["uri"].get<std::string>()));
  return files;
}

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
    for (const auto& declared : files->buffers)
      if (names(path, declared.first)) buffer = &declared;
    if (!buffer) {
      for (const std::string& image : files->images)
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

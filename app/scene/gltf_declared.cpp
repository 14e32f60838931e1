#include "scene/gltf_declared.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cstring>

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

// The URI of a buffer or image that names a file (not a data: URI), or nullptr.
const std::string* externalUri(const nlohmann::json& item) {
  if (!item.is_object()) return nullptr;
  const auto uri = item.find("uri");
  if (uri == item.end() || !uri->is_string()) return nullptr;
  const std::string& text = uri->get_ref<const std::string&>();
  return text.rfind("data:", 0) == 0 ? nullptr : &text;
}

void names(const nlohmann::json& root, const char* key, std::vector<std::string>& out) {
  const auto it = root.find(key);
  if (it == root.end() || !it->is_array()) return;
  for (const nlohmann::json& name : *it)
    if (name.is_string()) out.push_back(name.get<std::string>());
}

}  // namespace

GltfDeclared readGltfDeclared(const std::vector<unsigned char>& bytes, bool binary) {
  GltfDeclared declared;
  const unsigned char* json = bytes.data();
  size_t length = bytes.size();
  if (binary) {  // 12-byte header (magic, version, length), then the JSON chunk: length, "JSON", bytes
    if (bytes.size() < 20 || std::memcmp(bytes.data() + 16, "JSON", 4) != 0) return declared;
    std::uint32_t chunkLength = 0;
    std::memcpy(&chunkLength, bytes.data() + 12, 4);
    if (chunkLength > bytes.size() - 20) return declared;
    json = bytes.data() + 20;
    length = chunkLength;
  }
  const nlohmann::json root = nlohmann::json::parse(json, json + length, nullptr, false);
  if (!root.is_object()) return declared;
  if (const auto buffers = root.find("buffers"); buffers != root.end() && buffers->is_array())
    for (const nlohmann::json& buffer : *buffers)
      if (const std::string* uri = externalUri(buffer)) {
        const auto byteLength = buffer.find("byteLength");
        const bool valid = byteLength != buffer.end() && byteLength->is_number_unsigned();
        declared.buffers.emplace_back(urlDecoded(*uri), valid ? byteLength->get<std::uint64_t>() : 0);
      }
  if (const auto images = root.find("images"); images != root.end() && images->is_array())
    for (const nlohmann::json& image : *images)
      if (const std::string* uri = externalUri(image)) declared.images.push_back(urlDecoded(*uri));
  names(root, "extensionsRequired", declared.extensionsRequired);
  names(root, "extensionsUsed", declared.extensionsUsed);
  return declared;
}

const char* unsupportedGeometryExtension(const std::string& name) {
  if (name == "KHR_draco_mesh_compression") return "Draco-compressed meshes";
  if (name == "EXT_meshopt_compression") return "meshopt-compressed buffers";
  if (name == "KHR_mesh_quantization") return "quantized (integer) vertex attributes";
  if (name == "EXT_mesh_gpu_instancing") return "GPU-instanced meshes";
  return nullptr;
}

std::string unsupportedExtensionMessage(const std::string& name, const char* what) {
  return std::string(what) + " (" + name + ") are not supported";
}

#include "scene/scene_gltf.h"

// The Debian libtinygltf.so is built with stb_image and the default file system, so the
// header is used with no configuration macros (they would change what the header
// declares, not the library), and without TINYGLTF_IMPLEMENTATION.
#include <tiny_gltf.h>

#include "base/input_error.h"
#include "base/json_input.h"
#include "scene/gltf_file_access.h"
#include "scene/mesh_normals.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <set>
#include <stdexcept>

namespace {

// A node graph is a forest by the spec; these bound what a hostile file can make us do
// (deep chains exhaust the stack, nodes shared by many parents multiply instances).
constexpr int kMaxNodeDepth = 256;
constexpr size_t kMaxNodeVisits = 1'000'000;
const glm::vec3 kDefaultColor{0.8f};

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string componentTypeName(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_INT: return "INT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    default: return "component type " + std::to_string(type);
  }
}

std::string typeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "type " + std::to_string(type);
  }
}

// tinygltf's messages are newline-separated lists; one line reads better in a log.
std::string oneLine(std::string text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  std::string result;
  for (char c : text) {
    if (c == '\n')
      result += "; ";
    else if (c != '\r')
      result += c;
  }
  return result;
}

// Shadows need no textures; skipping the decode also keeps stb_image away from
// untrusted image bytes.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int,
               const unsigned char*, int, void*) {
  return true;
}

// A validated accessor: `count` elements, element i starts at data + i * stride, and all
// of them lie inside the buffer.
struct AccessorView {
  const unsigned char* data = nullptr;
  size_t stride = 0;
  size_t count = 0;
  int componentType = 0;
};

class Importer {
 public:
  Importer(const std::string& path, const tinygltf::Model& model,
           std::vector<std::string>& warnings, SceneBudget& budget)
      : path_(path), model_(model), warnings_(warnings), budget_(budget) {}

  std::vector<SceneObject> run(const glm::dmat4& worldFromFile);
  // Per loaded object, the nodes from its root to its mesh's node (for its animation).
  const std::vector<std::vector<int>>& objectNodePaths() const { return objectPaths_; }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(path_ + ": " + what);
  }
  // One warning per distinct problem, not one per instance of a shared mesh.
  void warn(const std::string& what) {
    if (warned_.insert(what).second) warnings_.push_back(path_ + ": " + what);
  }

  void checkExtensions();
  std::vector<int> rootNodes();
  void visit(int node, int parent, const glm::dmat4& parentWorld, int depth);
  glm::dmat4 localTransform(int nodeIndex);
  void addMeshInstance(int nodeIndex, int meshIndex, const glm::dmat4& world);
  bool addPrimitive(const tinygltf::Mesh& mesh, size_t primitiveIndex,
                    const std::string& objectName, const glm::dmat4& world, bool mirrored);
  AccessorView view(int accessorIndex, const std::string& where, int wantType,
                    std::initializer_list<int> wantComponents);
  std::vector<glm::vec3> readVec3(int accessorIndex, const std::string& where);
  std::vector<std::uint32_t> readIndices(int accessorIndex, const std::string& where,
                                         size_t vertexCount);
  glm::vec3 materialColor(int material, const std::string& where);

  std::string path_;
  const tinygltf::Model& model_;
  std::vector<std::string>& warnings_;
  SceneBudget& budget_;
  std::set<std::string> warned_;
  std::vector<char> onPath_;  // nodes on the current root-to-node path: a revisit is a cycle
  size_t visits_ = 0;
  size_t triangles_ = 0;
  size_t skippedPrimitives_ = 0;
  size_t singularInstances_ = 0;
  std::vector<SceneObject> objects_;
  std::vector<int> nodePath_;
  std::vector<std::vector<int>> objectPaths_;
};

std::vector<SceneObject> Importer::run(const glm::dmat4& worldFromFile) {
  // tinygltf reads glTF 1.0 JSON too, without its meshes: say so rather than "no triangles".
  const std::string& version = model_.asset.version;
  if (version.empty() || version[0] != '2')
    fail("glTF " + (version.empty() ? std::string("without asset.version") : printable(version)) +
         " is not supported (only glTF 2.0)");
  checkExtensions();
  if (!model_.skins.empty()) warn("skins are ignored; skinned meshes keep their bind pose");
  onPath_.assign(model_.nodes.size(), 0);
  for (int root : rootNodes()) visit(root, -1, worldFromFile, 0);
  if (objects_.empty())
    fail("no triangles to load (" + std::to_string(model_.meshes.size()) + " meshes, " +
         std::to_string(model_.nodes.size()) + " nodes, " + std::to_string(model_.scenes.size()) +
         " scenes, " + std::to_string(skippedPrimitives_) + " non-triangle primitives skipped, " +
         std::to_string(singularInstances_) + " mesh instances with a singular transform)");
  budget_.triangles -= triangles_;
  budget_.objects -= objects_.size();
  return std::move(objects_);
}

void Importer::checkExtensions() {
  for (const std::string& name : model_.extensionsRequired) {
    if (const char* what = unsupportedGeometryExtension(name)) fail(unsupportedExtensionMessage(name, what));
    warn("ignoring required extension " + name);
  }
}

std::vector<int> Importer::rootNodes() {
  if (!model_.scenes.empty()) {
    int scene = model_.defaultScene == -1 ? 0 : model_.defaultScene;
    if (scene < 0 || static_cast<size_t>(scene) >= model_.scenes.size())
      fail("default scene " + std::to_string(scene) + " out of range (" +
           std::to_string(model_.scenes.size()) + " scenes)");
    return model_.scenes[scene].nodes;
  }
  // No scenes: the spec leaves it to the application; show every node nobody parents.
  std::vector<char> isChild(model_.nodes.size(), 0);
  for (const tinygltf::Node& node : model_.nodes)
    for (int child : node.children)
      if (child >= 0 && static_cast<size_t>(child) < isChild.size()) isChild[child] = 1;
  std::vector<int> roots;
  for (size_t i = 0; i < isChild.size(); ++i)
    if (!isChild[i]) roots.push_back(static_cast<int>(i));
  return roots;
}

void Importer::visit(int node, int parent, const glm::dmat4& parentWorld, int depth) {
  const std::string from = parent < 0 ? "scene" : "node " + std::to_string(parent);
  if (node < 0 || static_cast<size_t>(node) >= model_.nodes.size())
    fail(from + " refers to node " + std::to_string(node) + ", out of range (" +
         std::to_string(model_.nodes.size()) + " nodes)");
  if (onPath_[node])
    fail("node graph has a cycle: node " + std::to_string(node) + " is its own ancestor");
  if (depth >= kMaxNodeDepth)
    fail("node hierarchy deeper than " + std::to_string(kMaxNodeDepth) + " levels");
  if (++visits_ > kMaxNodeVisits)
    fail("more than " + std::to_string(kMaxNodeVisits) +
         " node instances (nodes shared by several parents?)");
  onPath_[node] = 1;
  nodePath_.push_back(node);
  const glm::dmat4 world = parentWorld * localTransform(node);
  const tinygltf::Node& n = model_.nodes[node];
  if (n.mesh != -1) addMeshInstance(node, n.mesh, world);
  for (int child : n.children) visit(child, node, world, depth + 1);
  nodePath_.pop_back();
  onPath_[node] = 0;
}

glm::dmat4 Importer::localTransform(int nodeIndex) {
  const tinygltf::Node& node = model_.nodes[nodeIndex];
  const std::string where = "node " + std::to_string(nodeIndex);
  for (const std::vector<double>* values :
       {&node.matrix, &node.translation, &node.rotation, &node.scale})
    for (double v : *values)
      if (!std::isfinite(v)) fail(where + ": non-finite transform value");
  if (!node.matrix.empty()) {
    if (node.matrix.size() != 16)
      fail(where + ": matrix has " + std::to_string(node.matrix.size()) + " values, not 16");
    glm::dmat4 m;
    std::copy(node.matrix.begin(), node.matrix.end(), glm::value_ptr(m));  // column-major
    return m;
  }
  auto checkSize = [&](const std::vector<double>& v, size_t want, const char* name) {
    if (!v.empty() && v.size() != want)
      fail(where + ": " + name + " has " + std::to_string(v.size()) + " values, not " +
           std::to_string(want));
  };
  checkSize(node.translation, 3, "translation");
  checkSize(node.rotation, 4, "rotation");
  checkSize(node.scale, 3, "scale");
  glm::dmat4 m(1.0);
  if (!node.translation.empty())
    m = glm::translate(m, {node.translation[0], node.translation[1], node.translation[2]});
  if (!node.rotation.empty()) {
    glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    const double length = glm::length(q);
    if (!(length > 1e-12)) fail(where + ": rotation quaternion has zero length");
    m = m * glm::mat4_cast(q / length);
  }
  if (!node.scale.empty()) m = glm::scale(m, {node.scale[0], node.scale[1], node.scale[2]});
  return m;
}

void Importer::addMeshInstance(int nodeIndex, int meshIndex, const glm::dmat4& world) {
  if (meshIndex < 0 || static_cast<size_t>(meshIndex) >= model_.meshes.size())
    fail("node " + std::to_string(nodeIndex) + ": mesh " + std::to_string(meshIndex) +
         " out of range (" + std::to_string(model_.meshes.size()) + " meshes)");
  const double det = glm::determinant(glm::dmat3(world));
  if (!std::isfinite(det) || det == 0) {
    // Zero scale is a legitimate way to hide a node; there is no surface to shade.
    warn("node " + std::to_string(nodeIndex) + " has a singular transform; its mesh is skipped");
    ++singularInstances_;
    return;
  }
  const tinygltf::Mesh& mesh = model_.meshes[meshIndex];
  const tinygltf::Node& node = model_.nodes[nodeIndex];
  std::string name = !node.name.empty()   ? node.name
                     : !mesh.name.empty() ? mesh.name
                                          : "node " + std::to_string(nodeIndex);
  for (size_t i = 0; i < mesh.primitives.size(); ++i) {
    const std::string objectName =
        mesh.primitives.size() > 1 ? name + "#" + std::to_string(i) : name;
    addPrimitive(mesh, i, objectName, world, det < 0);
  }
}

AccessorView Importer::view(int accessorIndex, const std::string& where, int wantType,
                            std::initializer_list<int> wantComponents) {
  if (accessorIndex < 0 || static_cast<size_t>(accessorIndex) >= model_.accessors.size())
    fail(where + ": accessor " + std::to_string(accessorIndex) + " out of range (" +
         std::to_string(model_.accessors.size()) + " accessors)");
  const tinygltf::Accessor& a = model_.accessors[accessorIndex];
  const std::string at = where + " (accessor " + std::to_string(accessorIndex) + ")";
  if (a.type != wantType)
    fail(at + ": type " + typeName(a.type) + ", expected " + typeName(wantType));
  if (std::find(wantComponents.begin(), wantComponents.end(), a.componentType) ==
      wantComponents.end()) {
    std::string valid;
    for (int c : wantComponents) valid += (valid.empty() ? "" : " or ") + componentTypeName(c);
    fail(at + ": component type " + componentTypeName(a.componentType) + ", expected " + valid);
  }
  // Every type accepted here is one the spec forbids to be normalized.
  if (a.normalized)
    fail(at + ": " + componentTypeName(a.componentType) + " must not be normalized");
  if (a.sparse.isSparse) fail(at + ": sparse accessors are not supported");
  if (a.count == 0) fail(at + ": count is 0");
  if (a.bufferView < 0) fail(at + ": no bufferView (all-zero data)");
  if (static_cast<size_t>(a.bufferView) >= model_.bufferViews.size())
    fail(at + ": bufferView " + std::to_string(a.bufferView) + " out of range (" +
         std::to_string(model_.bufferViews.size()) + " bufferViews)");
  const tinygltf::BufferView& bv = model_.bufferViews[a.bufferView];
  const std::string bvName = "bufferView " + std::to_string(a.bufferView);
  if (bv.buffer < 0 || static_cast<size_t>(bv.buffer) >= model_.buffers.size())
    fail(at + ": " + bvName + " refers to buffer " + std::to_string(bv.buffer) +
         ", out of range (" + std::to_string(model_.buffers.size()) + " buffers)");
  const std::vector<unsigned char>& bytes = model_.buffers[bv.buffer].data;
  if (bv.byteOffset > bytes.size() || bv.byteLength > bytes.size() - bv.byteOffset)
    fail(at + ": " + bvName + " bytes [" + std::to_string(bv.byteOffset) + ", +" +
         std::to_string(bv.byteLength) + ") exceed buffer " + std::to_string(bv.buffer) + " (" +
         std::to_string(bytes.size()) + " bytes)");
  const size_t component = static_cast<size_t>(
      tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType)));
  const size_t element =
      component *
      static_cast<size_t>(tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type)));
  size_t stride = element;
  if (bv.byteStride != 0) {
    if (bv.byteStride < element || bv.byteStride > 252 || bv.byteStride % component != 0)
      fail(at + ": " + bvName + " byteStride " + std::to_string(bv.byteStride) + " invalid for " +
           std::to_string(element) + "-byte elements");
    stride = bv.byteStride;
  }
  // Written as subtractions so that hostile sizes cannot overflow.
  if (a.byteOffset > bv.byteLength || bv.byteLength - a.byteOffset < element ||
      (a.count - 1) > (bv.byteLength - a.byteOffset - element) / stride)
    fail(at + ": " + std::to_string(a.count) + " elements of stride " + std::to_string(stride) +
         " from offset " + std::to_string(a.byteOffset) + " exceed " + bvName + " (" +
         std::to_string(bv.byteLength) + " bytes)");
  return {bytes.data() + bv.byteOffset + a.byteOffset, stride, a.count, a.componentType};
}

std::vector<glm::vec3> Importer::readVec3(int accessorIndex, const std::string& where) {
  const AccessorView v =
      view(accessorIndex, where, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT});
  std::vector<glm::vec3> result(v.count);
  for (size_t i = 0; i < v.count; ++i)
    std::memcpy(&result[i], v.data + i * v.stride, sizeof(glm::vec3));  // unaligned-safe
  return result;
}

std::vector<std::uint32_t> Importer::readIndices(int accessorIndex, const std::string& where,
                                                 size_t vertexCount) {
  const AccessorView v =
      view(accessorIndex, where + " indices", TINYGLTF_TYPE_SCALAR,
           {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
            TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT});
  std::vector<std::uint32_t> result(v.count);
  for (size_t i = 0; i < v.count; ++i) {
    const unsigned char* p = v.data + i * v.stride;
    std::uint32_t index = 0;
    if (v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
      index = *p;
    } else if (v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
      std::uint16_t s;
      std::memcpy(&s, p, 2);
      index = s;
    } else {
      std::memcpy(&index, p, 4);
    }
    if (index >= vertexCount)
      fail(where + ": index " + std::to_string(index) + " out of range (" +
           std::to_string(vertexCount) + " vertices)");
    result[i] = index;
  }
  return result;
}

glm::vec3 Importer::materialColor(int material, const std::string& where) {
  if (material == -1) return kDefaultColor;
  if (material < 0 || static_cast<size_t>(material) >= model_.materials.size()) {
    warn(where + ": material " + std::to_string(material) + " out of range; using grey");
    return kDefaultColor;
  }
  const std::vector<double>& f = model_.materials[material].pbrMetallicRoughness.baseColorFactor;
  if (f.size() < 3 || !finite(glm::dvec3(f[0], f[1], f[2]))) {
    warn("material " + std::to_string(material) + ": invalid baseColorFactor; using grey");
    return kDefaultColor;
  }
  return glm::clamp(glm::vec3(f[0], f[1], f[2]), 0.0f, 1.0f);
}

bool Importer::addPrimitive(const tinygltf::Mesh& mesh, size_t primitiveIndex,
                            const std::string& objectName, const glm::dmat4& world, bool mirrored) {
  const tinygltf::Primitive& p = mesh.primitives[primitiveIndex];
  const std::string where = (mesh.name.empty() ? "mesh" : "mesh '" + printable(mesh.name) + "'") +
                            " primitive " + std::to_string(primitiveIndex);
  const int mode = p.mode == -1 ? TINYGLTF_MODE_TRIANGLES : p.mode;
  if (mode != TINYGLTF_MODE_TRIANGLES) {
    static const char* const names[] = {"POINTS",    "LINES",          "LINE_LOOP",   "LINE_STRIP",
                                        "TRIANGLES", "TRIANGLE_STRIP", "TRIANGLE_FAN"};
    const std::string name = mode >= 0 && mode <= 6 ? names[mode] : "invalid";
    warn(where + ": mode " + std::to_string(mode) + " (" + name + ") is not TRIANGLES; skipped");
    ++skippedPrimitives_;
    return false;
  }
  const auto position = p.attributes.find("POSITION");
  if (position == p.attributes.end()) {
    warn(where + ": no POSITION attribute; skipped");
    ++skippedPrimitives_;
    return false;
  }
  if (!p.targets.empty()) warn(where + ": morph targets are ignored");

  Mesh out;
  out.positions = readVec3(position->second, where + " POSITION");
  const size_t vertexCount = out.positions.size();
  if (vertexCount > std::numeric_limits<std::uint32_t>::max())
    fail(where + ": too many vertices (" + std::to_string(vertexCount) + ")");
  for (size_t i = 0; i < vertexCount; ++i)
    if (!finite(glm::dvec3(out.positions[i])))
      fail(where + ": POSITION " + std::to_string(i) + " is not finite");
  if (p.indices != -1) {
    out.indices = readIndices(p.indices, where, vertexCount);
  } else {
    out.indices.resize(vertexCount);
    for (size_t i = 0; i < vertexCount; ++i) out.indices[i] = static_cast<std::uint32_t>(i);
  }
  if (out.indices.size() % 3 != 0)
    fail(where + ": " + std::to_string(out.indices.size()) +
         " indices is not a multiple of 3 for TRIANGLES");
  // The scene's budget (app/scene/scene.h), shared by every file of the scene.
  triangles_ += out.triangleCount();
  if (triangles_ > budget_.triangles)
    fail("more than the scene budget of " + std::to_string(kMaxSceneTriangles) +
         " triangles after instancing (" + std::to_string(kMaxSceneTriangles - budget_.triangles) +
         " already in the scene)");
  if (objects_.size() + 1 > budget_.objects)
    fail("more than the scene budget of " + std::to_string(kMaxSceneObjects) +
         " mesh instances (" + std::to_string(kMaxSceneObjects - budget_.objects) +
         " already in the scene)");

  const auto normal = p.attributes.find("NORMAL");
  if (normal != p.attributes.end()) {
    out.normals = readVec3(normal->second, where + " NORMAL");
    if (out.normals.size() != vertexCount)
      fail(where + ": " + std::to_string(out.normals.size()) + " normals for " +
           std::to_string(vertexCount) + " positions");
  }

  // To world space. Mirroring transforms flip the winding; undo that so counter-clockwise
  // stays front-facing, as the spec requires.
  for (glm::vec3& q : out.positions) {
    q = glm::vec3(world * glm::dvec4(glm::dvec3(q), 1.0));
    if (!finite(glm::dvec3(q))) fail(where + ": position not finite after the node transforms");
  }
  if (mirrored)
    for (size_t t = 0; t < out.triangleCount(); ++t)
      std::swap(out.indices[3 * t + 1], out.indices[3 * t + 2]);

  if (out.normals.empty()) {
    makeFlatNormals(out);
  } else {
    const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(world)));
    std::vector<char> bad(vertexCount, 0);
    size_t badInFile = 0;
    for (size_t i = 0; i < vertexCount; ++i) {
      const glm::dvec3 n = out.normals[i];
      const double length = glm::length(n);
      if (!std::isfinite(length) || length < 1e-6) {
        bad[i] = 1;
        ++badInFile;
        continue;
      }
      const glm::dvec3 w = normalMatrix * (n / length);
      const double wl = glm::length(w);
      if (!std::isfinite(wl) || wl == 0)
        bad[i] = 1;  // extreme scales can lose it
      else
        out.normals[i] = glm::vec3(w / wl);
    }
    if (badInFile > 0)
      warn(where + ": " + std::to_string(badInFile) +
           " non-finite or zero-length normals replaced by face normals");
    if (std::find(bad.begin(), bad.end(), 1) != bad.end()) repairNormals(out, bad);
  }
  if (out.indices.empty()) return false;

  SceneObject object;
  object.name = objectName;
  object.mesh = std::move(out);
  object.baseColor = materialColor(p.material, where);
  objects_.push_back(std::move(object));
  objectPaths_.push_back(nodePath_);
  return true;
}

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

std::vector<SceneObject> loadGltf(const std::string& path, const glm::mat4& worldFromFile,
                                  std::vector<std::string>& warnings, SceneBudget* budget,
                                  GltfAnimation* animation) {
  auto fail = [&](const std::string& what) { throw InputError(path + ": " + what); };
  std::error_code error;
  // A FIFO, directory, device or symlink loop says what it is (not "no such file").
  if (std::string problem = regularFileProblem(path); !problem.empty()) fail(problem);
  // tinygltf passes sizes as 32 bits; larger files would be read truncated.
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (size >= kMaxFileBytes) fail("files of 4 GiB or more are not supported");
  SceneBudget whole;
  SceneBudget& shared = budget ? *budget : whole;
  if (size > shared.fileBytes)
    fail("reading it would pass the scene's limit of " + std::to_string(kMaxSceneFileBytes >> 20) +
         " MiB of glTF files and buffers in all (not read)");
  shared.fileBytes -= size;
  std::vector<unsigned char> bytes;
  std::string problem;
  if (!readRegularFile(&bytes, &problem, path, nullptr)) fail(oneLine(problem));
  return loadGltfFromMemory(bytes, path, worldFromFile, warnings, &shared, animation);
}

std::vector<SceneObject> loadGltfFromMemory(const std::vector<unsigned char>& bytes,
                                            const std::string& path, const glm::mat4& worldFromFile,
                                            std::vector<std::string>& warnings, SceneBudget* budget,
                                            GltfAnimation* animation) {
  auto fail = [&](const std::string& what) { throw InputError(path + ": " + what); };
  for (int c = 0; c < 4; ++c)
    if (!finite(glm::dvec3(worldFromFile[c])) || !std::isfinite(worldFromFile[c][3]))
      fail("non-finite placement transform");
  const std::string ext = lowerExtension(path);
  if (ext != ".gltf" && ext != ".glb")
    fail("unknown extension '" + ext + "' (expected .gltf or .glb)");
  if (bytes.size() >= kMaxFileBytes) fail("files of 4 GiB or more are not supported");

  // One read of the JSON before tinygltf's (gltf_declared.h): an unsupported geometry
  // extension is named before tinygltf fails on its accessors with a message that names
  // neither, and the buffers it declares bound what is read.
  const GltfDeclared declared = readGltfDeclared(bytes, ext == ".glb");
  for (const std::string& name : declared.extensionsRequired)
    if (const char* what = unsupportedGeometryExtension(name)) fail(unsupportedExtensionMessage(name, what));

  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(skipImage, nullptr);
  // Buffers are read only at their declared byteLength and within the scene's budget of
  // bytes read (gltf_file_access.h): a 48-byte buffer naming a 2 GiB file is refused unread.
  SceneBudget whole;
  SceneBudget& shared = budget ? *budget : whole;
  GltfFiles files{&declared, &shared.fileBytes};
  loader.SetFsCallbacks({regularFileExists, unexpandedPath, readRegularFile, refuseWrite, &files});
  tinygltf::Model model;
  std::string err, warn;
  const std::string baseDir = std::filesystem::path(path).parent_path().string();
  bool ok = false;
  try {
    ok = ext == ".glb"
             ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                           unsigned(bytes.size()), baseDir)
             : loader.LoadASCIIFromString(&model, &err, &warn,
                                          reinterpret_cast<const char*>(bytes.data()),
                                          unsigned(bytes.size()), baseDir);
  } catch (const std::exception& e) {
    fail(std::string("tinygltf: ") + e.what());
  }
  // tinygltf sometimes reports an error yet returns true; both mean the file is broken.
  if (!ok || !err.empty()) {
    std::string message =
        err.empty() ? "tinygltf could not load it" : "tinygltf: " + printable(oneLine(err), 400);
    // Used but not required: the file promises a fallback; name the extension if it failed.
    for (const std::string& name : declared.extensionsUsed)
      if (const char* what = unsupportedGeometryExtension(name))
        message += " (the file uses " + unsupportedExtensionMessage(name, what) + ")";
    fail(message);
  }
  if (!warn.empty()) warnings.push_back(path + ": tinygltf: " + printable(oneLine(warn), 400));

  Importer importer(path, model, warnings, shared);
  std::vector<SceneObject> objects = importer.run(glm::dmat4(worldFromFile));
  if (animation)
    *animation = readGltfAnimation(model, importer.objectNodePaths(), glm::dmat4(worldFromFile),
                                   path, warnings);
  return objects;
}

#include "support/scene_writer.h"

#include <fstream>

namespace fs = std::filesystem;
using nlohmann::json;

json groundAndPlateScene() {
  return {{"name", "ground and plate"},
          {"objects", json::array({{{"ground", {{"size", 20}, {"y", 0}}}},
                                   {{"ground", {{"size", 1.5}, {"y", 1}}},
                                    {"name", "plate"},
                                    {"receiver_only", false}}})},
          {"light", {{"center", {0, 4, 0}}, {"forward", {0, -1, 0}}, {"up", {0, 0, -1}},
                     {"width", 1}, {"height", 1}}},
          {"camera", {{"position", {0, 3, 6}}, {"target", {0, 0, 0}}}}};
}

std::string writeInstancedGltf(const TempDirectory& dir, const std::string& name, int levels,
                               int fanout, int leaves, int trianglesPerMesh,
                               const std::string& version, double leafScale) {
  // 1. The mesh: a strip of small triangles along x.
  std::vector<float> positions;
  for (int t = 0; t < trianglesPerMesh; ++t) {
    const float x = 0.01f * float(t);
    for (float v : {x, 0.f, 0.f, x + 0.01f, 0.f, 0.f, x, 0.01f, 0.f}) positions.push_back(v);
  }
  const std::string bin(reinterpret_cast<const char*>(positions.data()), positions.size() * 4);
  dir.write(name + ".bin", bin);
  // 2. Nodes: leaves first (the mesh), then each level groups all nodes of the level below.
  json nodes = json::array();
  std::vector<int> below;
  for (int i = 0; i < leaves; ++i) {
    json leaf = {{"mesh", 0}, {"translation", {0.0, 0.02 * i, 0.0}}};
    if (leafScale != 1.0) leaf["scale"] = {leafScale, leafScale, leafScale};
    below.push_back(int(nodes.size()));
    nodes.push_back(leaf);
  }
  for (int level = 0; level < levels; ++level) {
    std::vector<int> current;
    for (int i = 0; i < fanout; ++i) {
      current.push_back(int(nodes.size()));
      nodes.push_back({{"children", below}, {"translation", {0.0, 0.0, 0.05 * i}}});
    }
    below = current;
  }
  const json doc = {
      {"asset", {{"version", version}}},
      {"scene", 0},
      {"scenes", json::array({{{"nodes", below}}})},
      {"nodes", nodes},
      {"meshes", json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", 0}}}}})}}})},
      {"buffers", json::array({{{"uri", name + ".bin"}, {"byteLength", bin.size()}}})},
      {"bufferViews", json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", bin.size()}}})},
      {"accessors", json::array({{{"bufferView", 0},
                                  {"componentType", 5126},
                                  {"count", positions.size() / 3},
                                  {"type", "VEC3"},
                                  {"min", {0, 0, 0}},
                                  {"max", {0.01 * trianglesPerMesh, 0.01, 0}}}})}};
  return dir.write(name + ".gltf", doc.dump());
}

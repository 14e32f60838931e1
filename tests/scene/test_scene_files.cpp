// glTF import and the scene JSON format: real models load exactly, and every broken
// input (the assimp test corpus plus files written here) is refused with a message
// naming the file, or loads with a warning into a scene every consumer can trust.
#include <glm/gtc/matrix_transform.hpp>

#include "scene/mesh_builders.h"
#include "scene/scene_builtin.h"
#include "scene/scene_file.h"
#include "scene/scene_gltf.h"
#include "support/temp_directory.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const fs::path kModels = "/usr/share/assimp/models/glTF2";  // Debian assimp-testmodels
const std::string kEngine = (kModels / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb").string();
const std::string kExampleScene =
    std::string(PENUMBRA_SOURCE_DIR) + "/assets/scenes/engine_on_ground.json";

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// What every consumer relies on, checked more strictly than validateScene (unit normals).
void expectUsable(const std::vector<SceneObject>& objects, const std::string& what) {
  ASSERT_FALSE(objects.empty()) << what;
  for (const SceneObject& o : objects) {
    const Mesh& m = o.mesh;
    ASSERT_GT(m.indices.size(), 0u) << what << " " << o.name;
    ASSERT_EQ(m.indices.size() % 3, 0u) << what << " " << o.name;
    ASSERT_EQ(m.normals.size(), m.positions.size()) << what << " " << o.name;
    for (std::uint32_t i : m.indices) ASSERT_LT(i, m.positions.size()) << what << " " << o.name;
    for (const glm::vec3& p : m.positions) ASSERT_TRUE(finite(p)) << what << " " << o.name;
    for (const glm::vec3& n : m.normals) {
      ASSERT_TRUE(finite(n)) << what << " " << o.name;
      ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f) << what << " " << o.name;
    }
    ASSERT_TRUE(finite(o.baseColor)) << what;
  }
}

size_t triangles(const std::vector<SceneObject>& objects) {
  size_t count = 0;
  for (const SceneObject& o : objects) count += o.mesh.triangleCount();
  return count;
}

// A unique directory per test (TempDirectory): ctest runs the tests of this binary as
// parallel processes.
class SceneFilesTemp : public ::testing::Test {
 protected:
  const TempDirectory scratch_{"penumbra_scene_files"};
  const fs::path dir_ = scratch_.path();

  std::string write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
  }

  // Loads and expects a refusal whose message names the file and contains `needle`.
  void expectRefused(const std::string& path, const std::string& needle) {
    std::vector<std::string> warnings;
    try {
      loadGltf(path, glm::mat4(1), warnings);
      ADD_FAILURE() << path << " loaded but should be refused (" << needle << ")";
    } catch (const std::runtime_error& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(fs::path(path).filename().string()), std::string::npos) << message;
      EXPECT_NE(message.find(needle), std::string::npos) << message;
      std::cout << "  refused: " << message << "\n";
    }
  }
};

// One triangle in the z = 0 plane, counter-clockwise from +z, uint16 indices, with its
// binary buffer in a .bin next to the .gltf; tests break one thing at a time.
struct TinyGltf {
  std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::vector<float> normals;  // optional
  std::vector<std::uint16_t> indices = {0, 1, 2};
  json doc;

  std::vector<unsigned char> bin() const {
    std::vector<unsigned char> bytes(positions.size() * 4 + normals.size() * 4 + 8, 0);
    std::memcpy(bytes.data(), positions.data(), positions.size() * 4);
    if (!normals.empty())
      std::memcpy(bytes.data() + positions.size() * 4, normals.data(), normals.size() * 4);
    std::memcpy(bytes.data() + (positions.size() + normals.size()) * 4, indices.data(),
                indices.size() * 2);
    return bytes;
  }

  TinyGltf() { rebuild(); }
  void rebuild() {
    const size_t posBytes = positions.size() * 4, nrmBytes = normals.size() * 4;
    doc = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", json::array({{{"nodes", {0}}}})},
        {"nodes", json::array({{{"mesh", 0}}})},
        {"meshes", json::array({{{"name", "tri"},
                                 {"primitives", json::array({{{"attributes", {{"POSITION", 0}}},
                                                              {"indices", 1}}})}}})},
        {"buffers", json::array({{{"uri", "tiny.bin"}, {"byteLength", bin().size()}}})},
        {"bufferViews", json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", posBytes}},
                                     {{"buffer", 0},
                                      {"byteOffset", posBytes + nrmBytes},
                                      {"byteLength", indices.size() * 2}}})},
        {"accessors", json::array({{{"bufferView", 0},
                                    {"componentType", 5126},
                                    {"count", positions.size() / 3},
                                    {"type", "VEC3"}},
                                   {{"bufferView", 1},
                                    {"componentType", 5123},
                                    {"count", indices.size()},
                                    {"type", "SCALAR"}}})}};
    if (!normals.empty()) {
      doc["bufferViews"].push_back(
          {{"buffer", 0}, {"byteOffset", posBytes}, {"byteLength", nrmBytes}});
      doc["accessors"].push_back({{"bufferView", 2},
                                  {"componentType", 5126},
                                  {"count", normals.size() / 3},
                                  {"type", "VEC3"}});
      doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 2;
    }
  }
};

}  // namespace

TEST(SceneGltf, EngineLoadsAllTrianglesFinite) {
  std::vector<std::string> warnings;
  const std::vector<SceneObject> objects = loadGltf(kEngine, glm::mat4(1), warnings);
  EXPECT_EQ(triangles(objects), 121496u);
  expectUsable(objects, kEngine);
  Scene scene;
  scene.objects = objects;
  const Bounds b = scene.bounds();
  std::cout << "  engine: " << objects.size() << " objects, bounds (" << b.min.x << ", " << b.min.y
            << ", " << b.min.z << ") - (" << b.max.x << ", " << b.max.y << ", " << b.max.z << ")\n";
  EXPECT_NEAR(b.max.x - b.min.x, 743.4f, 1.0f);  // what assets/scenes/engine_on_ground.json scales
  for (const std::string& w : warnings) ADD_FAILURE() << "unexpected warning: " << w;
}

// The shipped dragon (assets/models, thesis Fig 4.1): every triangle, finite, its optional
// KHR_materials_* extensions ignored without a word; the built-in scene adds a floor and a
// wall that only receive, and the light sees the dragon.
TEST(SceneGltf, DragonSceneLoadsEveryTriangle) {
  std::vector<std::string> warnings;
  const Scene scene = loadScene("dragon", warnings);
  EXPECT_LE(warnings.size(), 1u);
  size_t dragonTriangles = 0, receiverOnly = 0;
  for (const SceneObject& object : scene.objects) {
    if (object.receiverOnly) ++receiverOnly;
    else dragonTriangles += object.mesh.indices.size() / 3;
  }
  EXPECT_EQ(dragonTriangles, 91216u);
  EXPECT_EQ(receiverOnly, 2u);  // floor and wall
  expectUsable(scene.objects, "dragon");
  const Bounds b = scene.bounds();
  EXPECT_GT(b.max.x - b.min.x, 2.0f);
}

// Outcome of each file of the assimp corpus with what its message must contain.
// tinygltf ignores schema errors outside geometry (wrongTypes/bad{Extension,Object,
// String,Uint}: a texture, material or name); those files draw correctly, so they load.
TEST(SceneGltf, AssimpCorpusRefusedOrRepaired) {
  ASSERT_TRUE(fs::is_directory(kModels)) << "install assimp-testmodels (scripts/setup.sh)";
  struct Case {
    const char* file;
    bool loads;
    const char* needle;
  };
  const Case cases[] = {
      {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", false, "POSITION 0 is not finite"},
      {"IndexOutOfRange/IndexOutOfRange.gltf", false, "index 255 out of range (24 vertices)"},
      {"IndexOutOfRange/AllIndicesOutOfRange.gltf", false, "out of range (24 vertices)"},
      {"wrongTypes/badArray.gltf", false, "no triangles"},
      {"wrongTypes/badNumber.gltf", false, "tinygltf"},
      {"wrongTypes/badExtension.gltf", true, ""},
      {"wrongTypes/badObject.gltf", true, ""},
      {"wrongTypes/badString.gltf", true, ""},
      {"wrongTypes/badUint.gltf", true, ""},
      {"MissingBin/BoxTextured.gltf", false, "BoxTextured0.bin"},
      {"BoxBadNormals-glTF-Binary/BoxBadNormals.glb", true, "normals replaced"},
      {"RecursiveNodes/RecursiveNodes.gltf", false, "cycle"},
      {"IncorrectVertexArrays/Cube.gltf", false, "not a multiple of 3"},
      {"TestNoRootNode/NoScene.gltf", false, "no triangles"},
      {"TestNoRootNode/SceneWithoutNodes.gltf", false, "no triangles"},
      {"draco/2CylinderEngine.gltf", false,
       "Draco-compressed meshes (KHR_draco_mesh_compression) are not supported"},
      {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_00.gltf", false, "no triangles"},
      {"BoxTextured-glTF/BoxTextured.gltf", true, ""},
      {"BoxTextured-glTF-Binary/BoxTextured.glb", true, ""},
  };
  for (const Case& c : cases) {
    const std::string path = (kModels / c.file).string();
    std::vector<std::string> warnings;
    try {
      const std::vector<SceneObject> objects = loadGltf(path, glm::mat4(1), warnings);
      std::cout << "  loaded (" << warnings.size() << " warnings): " << c.file << "\n";
      for (const std::string& w : warnings) std::cout << "    warning: " << w << "\n";
      EXPECT_TRUE(c.loads) << c.file << " loaded but should be refused";
      expectUsable(objects, c.file);
      if (*c.needle) {
        bool found = false;
        for (const std::string& w : warnings)
          found = found || w.find(c.needle) != std::string::npos;
        EXPECT_TRUE(found) << c.file << ": no warning contains '" << c.needle << "'";
      }
    } catch (const std::runtime_error& e) {
      const std::string message = e.what();
      std::cout << "  refused: " << message << "\n";
      EXPECT_FALSE(c.loads) << message;
      EXPECT_NE(message.find(fs::path(c.file).filename().string()), std::string::npos) << message;
      EXPECT_NE(message.find(c.needle), std::string::npos) << message;
    }
  }
}

TEST_F(SceneFilesTemp, TinyGltfBaselineLoadsWithFlatNormals) {
  TinyGltf t;
  const std::vector<unsigned char> bin = t.bin();
  write("tiny.bin", std::string(bin.begin(), bin.end()));
  std::vector<std::string> warnings;
  // Mixed-case extension on purpose: extensions are matched case-insensitively.
  const auto objects = loadGltf(write("tiny.GLTF", t.doc.dump()), glm::mat4(1), warnings);
  ASSERT_EQ(objects.size(), 1u);
  expectUsable(objects, "tiny");
  EXPECT_EQ(objects[0].name, "tri");
  for (const glm::vec3& n : objects[0].mesh.normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);
  EXPECT_TRUE(warnings.empty());
}

TEST_F(SceneFilesTemp, NodeTransformsAndMirroringKeepNormalsOutward) {
  TinyGltf t;
  t.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1};
  t.rebuild();
  t.doc["nodes"] = json::array(
      {{{"children", {1}}, {"translation", {1, 2, 3}}}, {{"mesh", 0}, {"scale", {-2, 2, 2}}}});
  const std::vector<unsigned char> bin = t.bin();
  write("tiny.bin", std::string(bin.begin(), bin.end()));
  std::vector<std::string> warnings;
  const auto objects = loadGltf(write("mirror.gltf", t.doc.dump()), glm::mat4(1), warnings);
  ASSERT_EQ(objects.size(), 1u);
  expectUsable(objects, "mirror");
  const Mesh& m = objects[0].mesh;
  EXPECT_EQ(m.positions[1], glm::vec3(-1, 2, 3));  // (1,0,0) scaled by -2, moved by (1,2,3)
  const glm::vec3 face = glm::cross(m.positions[m.indices[1]] - m.positions[m.indices[0]],
                                    m.positions[m.indices[2]] - m.positions[m.indices[0]]);
  EXPECT_GT(glm::dot(face, m.normals[0]), 0.0f) << "winding must follow the normals";
}

TEST_F(SceneFilesTemp, BadNormalsRepairedWithWarning) {
  TinyGltf t;
  t.normals = {0, 0, 1, NAN, 0, 0, 0, 0, 0};
  t.rebuild();
  const std::vector<unsigned char> bin = t.bin();
  write("tiny.bin", std::string(bin.begin(), bin.end()));
  std::vector<std::string> warnings;
  const auto objects = loadGltf(write("normals.gltf", t.doc.dump()), glm::mat4(1), warnings);
  expectUsable(objects, "normals");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("2 non-finite or zero-length normals"), std::string::npos)
      << warnings[0];
  for (const glm::vec3& n : objects[0].mesh.normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);
}

TEST_F(SceneFilesTemp, OwnBrokenFilesRefused) {
  TinyGltf base;
  const std::vector<unsigned char> bin = base.bin();
  write("tiny.bin", std::string(bin.begin(), bin.end()));
  auto variant = [&](const std::string& name, auto&& edit) {
    json doc = base.doc;
    edit(doc);
    return write(name, doc.dump());
  };
  expectRefused(variant("past_end.gltf", [](json& d) { d["accessors"][0]["count"] = 4; }),
                "exceed bufferView 0");
  expectRefused(
      variant("view_past_buffer.gltf", [](json& d) { d["bufferViews"][1]["byteLength"] = 400; }),
      "exceed buffer 0");
  expectRefused(
      variant("float_indices.gltf", [](json& d) { d["accessors"][1]["componentType"] = 5126; }),
      "component type FLOAT, expected UNSIGNED_BYTE or UNSIGNED_SHORT or UNSIGNED_INT");
  expectRefused(variant("vec2_positions.gltf", [](json& d) { d["accessors"][0]["type"] = "VEC2"; }),
                "type VEC2, expected VEC3");
  // tinygltf catches a few dangling indices itself; its message is passed on.
  expectRefused(
      variant("bad_accessor.gltf", [](json& d) { d["meshes"][0]["primitives"][0]["indices"] = 9; }),
      "accessor out of bounds");
  expectRefused(variant("bad_view.gltf", [](json& d) { d["accessors"][0]["bufferView"] = 9; }),
                "bufferView");
  expectRefused(variant("bad_buffer.gltf", [](json& d) { d["bufferViews"][0]["buffer"] = 5; }),
                "buffer");
  expectRefused(variant("bad_node.gltf",
                        [](json& d) {
                          d["scenes"][0]["nodes"] = {0, 4};
                        }),
                "node 4");
  expectRefused(variant("bad_mesh.gltf", [](json& d) { d["nodes"][0]["mesh"] = 3; }), "mesh 3");
  expectRefused(variant("normalized.gltf", [](json& d) { d["accessors"][1]["normalized"] = true; }),
                "must not be normalized");
  expectRefused(variant("bad_stride.gltf", [](json& d) { d["bufferViews"][0]["byteStride"] = 8; }),
                "byteStride 8 invalid");
  expectRefused(variant("sparse.gltf",
                        [](json& d) {
                          d["accessors"][0]["sparse"] = {
                              {"count", 1},
                              {"indices", {{"bufferView", 1}, {"componentType", 5123}}},
                              {"values", {{"bufferView", 0}}}};
                        }),
                "sparse");
  expectRefused(
      variant("cycle.gltf",
              [](json& d) {
                d["nodes"] = json::array(
                    {{{"mesh", 0}, {"children", {1}}}, {{"children", {2}}}, {{"children", {1}}}});
              }),
      "cycle");
  expectRefused(variant("deep.gltf",
                        [](json& d) {
                          json nodes = json::array();
                          for (int i = 0; i < 300; ++i) nodes.push_back({{"children", {i + 1}}});
                          nodes.push_back({{"mesh", 0}});
                          d["nodes"] = nodes;
                        }),
                "deeper than");
  expectRefused(variant("lines.gltf", [](json& d) { d["meshes"][0]["primitives"][0]["mode"] = 1; }),
                "1 non-triangle primitives skipped");
  expectRefused(variant("nan_matrix.gltf",
                        [](json& d) {
                          d["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0,
                                                     0, 0, 1, 0, 0, 0, 0, 1};
                          d["nodes"][0]["matrix"][12] = 1e300;  // finite, but not as a float
                        }),
                "not finite after the node transforms");

  TinyGltf outOfRange;
  outOfRange.indices = {0, 1, 7};
  outOfRange.rebuild();
  const std::vector<unsigned char> oorBin = outOfRange.bin();
  write("tiny.bin", std::string(oorBin.begin(), oorBin.end()));
  expectRefused(write("oor.gltf", outOfRange.doc.dump()), "index 7 out of range (3 vertices)");

  expectRefused(write("model.obj", "o cube"), "unknown extension '.obj'");
  expectRefused((dir_ / "missing.glb").string(), "no such file");
  expectRefused(write("garbage.gltf", "{ not json"), "tinygltf");

  std::ifstream engine(kEngine, std::ios::binary);
  const std::string glb((std::istreambuf_iterator<char>(engine)), std::istreambuf_iterator<char>());
  ASSERT_GT(glb.size(), 1000u);
  expectRefused(write("truncated.glb", glb.substr(0, glb.size() / 2)), "tinygltf");
  expectRefused(write("header_only.glb", glb.substr(0, 12)), "tinygltf");
  std::string wrongLength = glb;
  wrongLength[8] = '\xff';  // total length field larger than the file
  wrongLength[9] = '\xff';
  wrongLength[10] = '\xff';
  expectRefused(write("wrong_length.glb", wrongLength), "tinygltf");
}

// Scene JSON ---------------------------------------------------------------------------

TEST(SceneFile, ExampleSceneLoads) {
  std::vector<std::string> warnings;
  const Scene scene = loadSceneFile(kExampleScene, warnings);
  EXPECT_EQ(validateScene(scene), "");
  EXPECT_EQ(scene.triangleCount(), 121496u + 2u);
  EXPECT_TRUE(warnings.empty());
  const Bounds occluders = scene.bounds(true);
  const glm::vec3 extent = occluders.max - occluders.min;
  EXPECT_GT(std::max({extent.x, extent.y, extent.z}), 2.0f);
  EXPECT_LT(std::max({extent.x, extent.y, extent.z}), 3.0f);
  EXPECT_GT(occluders.min.y, 0.0f) << "the engine floats above the ground";
  EXPECT_LT(occluders.max.y, scene.light.center.y) << "the light is above the engine";
  ASSERT_TRUE(scene.objects.back().receiverOnly);
  EXPECT_EQ(scene.objects.back().name, "ground");
}

TEST(SceneFile, GroundQuadFacesUp) {
  const Mesh m = makeQuad(4, glm::translate(glm::mat4(1), {0, 1.5f, 0}));
  ASSERT_EQ(m.triangleCount(), 2u);
  for (size_t t = 0; t < 2; ++t) {
    const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                    c = m.positions[m.indices[3 * t + 2]];
    EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f);
  }
  for (const glm::vec3& p : m.positions) {
    EXPECT_EQ(p.y, 1.5f);
    EXPECT_EQ(std::abs(p.x), 2.0f);
  }
  for (const glm::vec3& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 1, 0));
}

TEST_F(SceneFilesTemp, MalformedSceneFilesNameTheProblem) {
  // Only a ground, so that each variant loads fast; the glTF path is tested separately.
  const json base = {{"objects", json::array({{{"ground", {{"size", 10}}}}})},
                     {"light",
                      {{"center", {0, 4, 0}},
                       {"forward", {0, -1, 0}},
                       {"up", {0, 0, -1}},
                       {"width", 1},
                       {"height", 1}}},
                     {"camera", {{"position", {0, 3, 6}}, {"target", {0, 0, 0}}}}};
  std::vector<std::string> warnings;
  EXPECT_EQ(loadSceneFile(write("base.json", base.dump()), warnings).objects.size(), 1u);

  auto expectError = [&](const std::string& name, const std::string& text,
                         std::initializer_list<const char*> needles) {
    const std::string path = write(name, text);
    try {
      std::vector<std::string> w;
      loadSceneFile(path, w);
      ADD_FAILURE() << name << " loaded";
    } catch (const std::runtime_error& e) {
      const std::string message = e.what();
      std::cout << "  " << message << "\n";
      EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
      for (const char* needle : needles)
        EXPECT_NE(message.find(needle), std::string::npos) << message;
    }
  };
  auto edited = [&](auto&& edit) {
    json doc = base;
    edit(doc);
    return doc.dump();
  };

  expectError("not_json.json", "{ \"objects\": [ ", {"not valid JSON", "line 1"});
  expectError("top_array.json", "[1, 2]", {"/: expected an object, got an array"});
  expectError("unknown_top.json", edited([](json& d) { d["lights"] = d["light"]; }),
              {"unknown key 'lights'", "valid keys: name, objects, light, camera"});
  expectError("unknown_obj.json", edited([](json& d) {
                d["objects"][0]["colour"] = {1, 0, 0};
              }),
              {"/objects/0: unknown key 'colour'", "color"});
  expectError("wrong_type.json", edited([](json& d) { d["light"]["width"] = "1.0"; }),
              {"/light/width: expected a number, got a string"});
  expectError("wrong_bool.json", edited([](json& d) { d["objects"][0]["receiver_only"] = 1; }),
              {"/objects/0/receiver_only: expected true or false"});
  expectError("short_vec.json", edited([](json& d) {
                d["light"]["center"] = {0, 4};
              }),
              {"/light/center: expected an array of 3 numbers, got an array of 2"});
  expectError("missing_light.json", edited([](json& d) { d.erase("light"); }),
              {"/light: missing (required)"});
  expectError("missing_size.json", edited([](json& d) { d["objects"][0]["ground"].erase("size"); }),
              {"/objects/0/ground/size: missing (required)"});
  std::string huge = base.dump();
  huge.replace(huge.find("\"width\":1"), 9, "\"width\":1e999");
  // nlohmann refuses the literal itself; a representable but absurd value is ours to refuse.
  expectError("huge.json", huge, {"not valid JSON", "1e999"});
  // A position is told the limit that applies to positions (the scene limit), not 1e30.
  expectError("large.json", edited([](json& d) { d["light"]["center"][1] = 1e35; }),
              {"/light/center/1: must be within +-1e+06 (the scene limit"});
  expectError("larger.json", edited([](json& d) { d["camera"]["position"][0] = 1e308; }),
              {"/camera/position/0: must be within +-1e+06", "got 1e+308"});
  expectError("large_up.json", edited([](json& d) { d["light"]["up"][0] = 1e35; }),
              {"/light/up/0: must be finite and within +-1e30"});
  expectError("negative_width.json", edited([](json& d) { d["light"]["width"] = -1; }),
              {"/light/width: must be positive"});
  expectError("negative_ground.json",
              edited([](json& d) { d["objects"][0]["ground"]["size"] = -5; }),
              {"/objects/0/ground/size: must be positive"});
  expectError("zero_scale.json", edited([](json& d) {
                d["objects"][0] = {{"gltf", kEngine}, {"scale", {1, 0, 1}}};
              }),
              {"/objects/0/scale: must be positive"});
  expectError("both_kinds.json", edited([](json& d) { d["objects"][0]["gltf"] = "x.glb"; }),
              {"/objects/0: needs exactly one of 'gltf' or 'ground'"});
  expectError("no_objects.json", edited([](json& d) { d["objects"] = json::array(); }),
              {"/objects: expected a non-empty array"});
  expectError("bad_color.json", edited([](json& d) {
                d["objects"][0]["color"] = {0.5, 2, 0};
              }),
              {"/objects/0/color/1: must be in [0, 1]"});
  expectError("parallel_light.json", edited([](json& d) {
                d["light"]["up"] = {0, 2, 0};
              }),
              {"/light/up: is parallel to forward"});
  expectError("camera_on_target.json", edited([](json& d) {
                d["camera"]["target"] = {0, 3, 6};
              }),
              {"/camera/target: must differ from position"});
  expectError("wide_fov.json", edited([](json& d) { d["camera"]["fov_y_degrees"] = 200; }),
              {"/camera/fov_y_degrees: must be in (1, 179)"});
  expectError("missing_gltf.json", edited([](json& d) {
                d["objects"][0] = {{"gltf", "models/nothing.glb"}};
              }),
              {"/objects/0/gltf: ", "models/nothing.glb: no such file"});
  expectError(
      "broken_gltf.json", edited([](json& d) {
        d["objects"][0] = {{"gltf", (kModels / "IndexOutOfRange/IndexOutOfRange.gltf").string()}};
      }),
      {"/objects/0/gltf: ", "IndexOutOfRange.gltf: mesh 'Mesh' primitive 0: index 255"});
}

TEST_F(SceneFilesTemp, SceneFileRelativePathsAndOverrides) {
  TinyGltf t;
  const std::vector<unsigned char> bin = t.bin();
  fs::create_directories(dir_ / "models");
  write("models/tiny.bin", std::string(bin.begin(), bin.end()));
  write("models/tiny.gltf", t.doc.dump());
  const json doc = {
      {"name", "relative"},
      {"objects", json::array({{{"gltf", "models/tiny.gltf"},
                                {"name", "a"},
                                {"translate", {0, 1, 0}},
                                {"rotate_degrees", {0, 90, 0}},
                                {"scale", 2},
                                {"color", {1, 0, 0}},
                                {"receiver_only", true}}})},
      {"light",
       {{"center", {0, 4, 0}},
        {"forward", {0, -1, 0}},
        {"up", {0, 0.5, -1}},
        {"width", 1},
        {"height", 2}}},
      {"camera", {{"position", {0, 3, 6}}, {"target", {0, 0, 0}}, {"fov_y_degrees", 30}}}};
  std::vector<std::string> warnings;
  const Scene scene = loadSceneFile(write("relative.json", doc.dump()), warnings);
  EXPECT_EQ(scene.name, "relative");
  ASSERT_EQ(scene.objects.size(), 1u);
  const SceneObject& o = scene.objects[0];
  EXPECT_EQ(o.name, "a/tri");
  EXPECT_EQ(o.baseColor, glm::vec3(1, 0, 0));
  EXPECT_TRUE(o.receiverOnly);
  // (1,0,0) scaled by 2, turned 90 degrees about +y to (0,0,-2), lifted by 1.
  EXPECT_NEAR(glm::distance(o.mesh.positions[1], glm::vec3(0, 1, -2)), 0.0f, 1e-5f);
  EXPECT_NEAR(o.mesh.normals[0].x, 1.0f, 1e-5f);  // +z turned about +y
  // The light's up was not perpendicular to forward: kept its perpendicular part, warned.
  EXPECT_NEAR(glm::dot(scene.light.forward, scene.light.up), 0.0f, 1e-6f);
  EXPECT_NEAR(scene.light.up.z, -1.0f, 1e-6f);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("relative.json: /light/up: not perpendicular"), std::string::npos)
      << warnings[0];
  EXPECT_EQ(scene.camera.fovYDegrees, 30.0f);
}

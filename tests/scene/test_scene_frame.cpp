// A researcher's own model, in its own units: a bare glTF is framed when it loads, a scene
// file whose camera sits inside the model is warned about, and frameScene() fits the camera,
// the ground and the light to models a million times apart in size. The checks project the
// model's bounds through the camera as the eye pass does (glm::lookAt / perspective).
#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene_builtin.h"
#include "scene/scene_frame.h"
#include "scene/scene_gltf.h"
#include "support/temp_directory.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <fstream>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A closed box (12 triangles) of the given size, its lowest corner at `origin`, written as
// .gltf + .bin into `dir`; returns the .gltf path.
std::string writeBox(const fs::path& dir, const std::string& name, glm::vec3 size, glm::vec3 origin,
                     const json& extra = json::object()) {
  std::vector<float> p;
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) p.push_back(origin[k] + ((i >> k) & 1 ? size[k] : 0.0f));
  const std::uint16_t faces[] = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                                 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  std::string bin(p.size() * 4 + sizeof faces, '\0');
  std::memcpy(bin.data(), p.data(), p.size() * 4);
  std::memcpy(bin.data() + p.size() * 4, faces, sizeof faces);
  std::ofstream(dir / (name + ".bin"), std::ios::binary) << bin;
  json doc = {
      {"asset", {{"version", "2.0"}}},
      {"scene", 0},
      {"scenes", json::array({{{"nodes", {0}}}})},
      {"nodes", json::array({{{"mesh", 0}}})},
      {"meshes", json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", 0}}},
                                                             {"indices", 1}}})}}})},
      {"buffers", json::array({{{"uri", name + ".bin"}, {"byteLength", bin.size()}}})},
      {"bufferViews", json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", p.size() * 4}},
                                   {{"buffer", 0},
                                    {"byteOffset", p.size() * 4},
                                    {"byteLength", sizeof faces}}})},
      {"accessors", json::array({{{"bufferView", 0}, {"componentType", 5126}, {"count", 8},
                                  {"type", "VEC3"}, {"min", {origin.x, origin.y, origin.z}},
                                  {"max", {origin.x + size.x, origin.y + size.y, origin.z + size.z}}},
                                 {{"bufferView", 1}, {"componentType", 5123}, {"count", 36},
                                  {"type", "SCALAR"}}})}};
  doc.update(extra);
  const fs::path path = dir / (name + ".gltf");
  std::ofstream(path) << doc.dump();
  return path.string();
}

bool inside(const Bounds& b, const glm::vec3& p) {
  return glm::all(glm::greaterThan(p, b.min)) && glm::all(glm::lessThan(p, b.max));
}

// The camera sees the model: outside its bounds, every corner of the bounds in front of the
// camera and inside the image (a 4:3 eye image, as the export's default is near), and the
// model covering a fair part of it (its projected box at least 30 % of the image height or
// width). The light: above the model, facing down at it.
void expectFramed(const Scene& scene, const std::string& what) {
  const Bounds b = framedBounds(scene);
  ASSERT_FALSE(b.empty()) << what;
  const Camera& c = scene.camera;
  EXPECT_FALSE(inside(b, c.position)) << what << ": camera inside " << boundsText(b);
  const glm::mat4 view = glm::lookAt(c.position, c.target, c.up);
  const float aspect = 4.0f / 3.0f;
  const glm::mat4 projection = glm::perspective(glm::radians(c.fovYDegrees), aspect, 1e-3f, 1e3f);
  glm::vec2 lo(1e9f), hi(-1e9f);
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner{i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y,
                           i & 4 ? b.max.z : b.min.z};
    const glm::vec4 eye = view * glm::vec4(corner, 1);
    ASSERT_LT(eye.z, 0) << what << ": a corner of the model is behind the camera";
    const glm::vec4 clip = projection * eye;
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    lo = glm::min(lo, ndc);
    hi = glm::max(hi, ndc);
  }
  EXPECT_GE(lo.x, -1.0f) << what;
  EXPECT_GE(lo.y, -1.0f) << what;
  EXPECT_LE(hi.x, 1.0f) << what;
  EXPECT_LE(hi.y, 1.0f) << what;
  const float cover = std::max(hi.x - lo.x, hi.y - lo.y) / 2.0f;
  EXPECT_GT(cover, 0.3f) << what << ": the model covers " << cover << " of the image";

  const AreaLight& l = scene.light;
  EXPECT_GT(l.center.y, b.max.y) << what << ": light not above the model";
  EXPECT_LT(l.forward.y, -0.5f) << what << ": light not facing down";
  // Its axis passes through the model's bounds.
  const glm::vec3 center = 0.5f * (b.min + b.max);
  const float along = glm::dot(center - l.center, l.forward);
  EXPECT_TRUE(inside(b, l.center + along * l.forward) ||
              glm::length(l.center + along * l.forward - center) < 1e-3f * glm::length(b.max - b.min))
      << what;
  // A light about as large as the model: a penumbra to see, not a point or a sky.
  const float side = std::max({b.max.x - b.min.x, b.max.y - b.min.y, b.max.z - b.min.z});
  EXPECT_GT(l.width, 0.1f * side) << what;
  EXPECT_LT(l.width, 2.0f * side) << what;
}

// The ground: receiver-only, under the model's lowest point, wider than the model.
void expectGround(const Scene& scene, const std::string& what) {
  const Bounds b = framedBounds(scene);
  bool found = false;
  for (const SceneObject& o : scene.objects) {
    if (!o.receiverOnly || o.name != "ground") continue;
    found = true;
    Bounds g;
    for (const glm::vec3& p : o.mesh.positions) g.extend(p);
    EXPECT_NEAR(g.max.y, b.min.y, 1e-4f * (b.max.y - b.min.y) + 1e-30f) << what;
    EXPECT_LT(g.min.x, b.min.x) << what;
    EXPECT_GT(g.max.x, b.max.x) << what;
    EXPECT_LT(g.min.z, b.min.z) << what;
    EXPECT_GT(g.max.z, b.max.z) << what;
  }
  EXPECT_TRUE(found) << what << ": no ground";
}

}  // namespace

// A bare glTF at 1000 and at 0.001 units: each gets a camera that sees it, a ground under it
// and a light above it; the scene's notes keep the file's own size.
TEST(SceneFrame, BareGltfAtHugeAndTinyScaleIsFramed) {
  const TempDirectory dir("penumbra_scene_frame");
  for (float unit : {1000.0f, 0.001f}) {
    const std::string path = writeBox(dir.path(), "box" + std::to_string(int(unit * 1000)),
                                      unit * glm::vec3(2, 1, 0.5f), unit * glm::vec3(5, 7, -3));
    std::vector<std::string> warnings;
    const Scene scene = loadScene(path, warnings);
    const std::string what = "unit " + std::to_string(unit);
    expectFramed(scene, what);
    expectGround(scene, what);
    ASSERT_EQ(scene.notes.size(), 1u) << what;
    EXPECT_NE(scene.notes[0].find("in file units"), std::string::npos) << scene.notes[0];
    EXPECT_TRUE(cameraWarnings(scene).empty()) << what;
    // 12 of the box, 2 of the ground.
    EXPECT_NE(sceneSummary(scene).find("14 triangles"), std::string::npos) << sceneSummary(scene);
  }
}

// A scene file that places a 500-unit model at scale 1 with the camera of a 2-unit scene (the
// Stanford bunny's case): the camera is inside it, and loading says so. frameScene() then fits
// camera, ground and light in the scene's own units without moving the model; at 1e-3 too.
TEST(SceneFrame, SceneFileCameraInsideTheModelIsWarnedThenFramed) {
  const TempDirectory dir("penumbra_scene_frame_json");
  for (float unit : {250.0f, 0.001f}) {
    const std::string model = writeBox(dir.path(), "big", unit * glm::vec3(2, 2, 1.6f),
                                       unit * glm::vec3(-1, -1, -0.8f));
    const json sceneJson = {
        {"name", "model at scale 1"},
        {"objects", json::array({{{"gltf", model}, {"name", "model"}},
                                 {{"ground", {{"size", 12}, {"y", 0}}}, {"receiver_only", true}}})},
        {"light", {{"center", {0, 3, 0}}, {"forward", {0, -1, 0}}, {"up", {0, 0, -1}},
                   {"width", 1}, {"height", 1}}},
        {"camera", {{"position", {0, 0.5f, 0.5f}}, {"target", {0, 0, 0}}}}};
    const std::string path = dir.write("scene.json", sceneJson.dump());
    std::vector<std::string> warnings;
    Scene scene = loadScene(path, warnings);
    const std::string what = "unit " + std::to_string(unit);
    bool warned = false;
    for (const std::string& w : warnings)
      warned = warned || w.find("Frame scene") != std::string::npos;
    EXPECT_EQ(warned, unit > 1) << what;  // inside at 250; at 0.001 the camera looks at it from afar
    const Bounds before = framedBounds(scene);
    frameScene(scene);
    const Bounds after = framedBounds(scene);
    EXPECT_EQ(before.min, after.min) << what << ": the model moved";
    EXPECT_EQ(before.max, after.max) << what;
    EXPECT_TRUE(validateScene(scene).empty()) << validateScene(scene);
    expectFramed(scene, what);
    expectGround(scene, what);
    EXPECT_TRUE(cameraWarnings(scene).empty()) << what;
  }
}

// A scene of occluders only gets a ground; framing twice changes nothing more.
TEST(SceneFrame, GroundAddedWhenMissingAndFramingIsStable) {
  Scene scene;
  scene.name = "box only";
  const TempDirectory dir("penumbra_scene_frame_stable");
  std::vector<std::string> warnings;
  scene.objects = loadGltf(writeBox(dir.path(), "b", {3, 1, 2}, {10, 20, 30}), glm::mat4(1), warnings);
  frameScene(scene);
  expectGround(scene, "added");
  const Scene once = scene;
  frameScene(scene);
  EXPECT_EQ(scene.objects.size(), once.objects.size());
  EXPECT_EQ(scene.camera.position, once.camera.position);
  EXPECT_EQ(scene.light.center, once.light.center);
}

// Compressed or quantized geometry is refused with the extension named, before tinygltf
// reports the missing bufferView of a Draco accessor; declared but not required is loaded
// (the file carries plain data too).
TEST(SceneFrame, UnsupportedRequiredExtensionsAreNamed) {
  const TempDirectory dir("penumbra_scene_frame_ext");
  const struct {
    const char* extension;
    const char* words;
  } cases[] = {{"KHR_draco_mesh_compression", "Draco-compressed meshes"},
               {"EXT_meshopt_compression", "meshopt-compressed buffers"},
               {"KHR_mesh_quantization", "quantized"}};
  for (const auto& c : cases) {
    const std::string path =
        writeBox(dir.path(), c.extension, {1, 1, 1}, {0, 0, 0},
                 {{"extensionsUsed", {c.extension}}, {"extensionsRequired", {c.extension}}});
    std::vector<std::string> warnings;
    try {
      loadScene(path, warnings);
      ADD_FAILURE() << c.extension << " loaded";
    } catch (const std::runtime_error& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(path), std::string::npos) << message;
      EXPECT_NE(message.find(std::string(c.words)), std::string::npos) << message;
      EXPECT_NE(message.find(std::string("(") + c.extension + ") are not supported"),
                std::string::npos)
          << message;
    }
  }
  const std::string usedOnly = writeBox(dir.path(), "used_only", {1, 1, 1}, {0, 0, 0},
                                        {{"extensionsUsed", {"KHR_draco_mesh_compression"}}});
  std::vector<std::string> warnings;
  EXPECT_NO_THROW(loadScene(usedOnly, warnings));
}

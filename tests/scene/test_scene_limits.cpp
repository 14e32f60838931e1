// Scene input (docs/reliability.md) at and past the limits every back end can represent. Extreme
// coordinates, node bombs and a scene over its budget are refused with the bound in the message;
// failed loads keep their warnings; hostile keys stay short and printable; the light's
// configurations the depth maps cannot show are warned about.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <string>

#include "base/input_error.h"
#include "scene/mesh_builders.h"
#include "scene/scene_builtin.h"
#include "scene/scene_checks.h"
#include "scene/scene_file.h"
#include "scene/scene_gltf.h"
#include "scene/scene_stress.h"
#include "support/refusal.h"
#include "support/scene_writer.h"

using nlohmann::json;

namespace {

// The message of the InputError loading `path` throws ("" and a test failure if none).
std::string refusal(const std::string& path) {
  std::vector<std::string> warnings;
  return refusalOf(path, [&] { loadScene(path, warnings); });
}

}  // namespace

TEST(SceneLimits, CoordinatesBeyondTheLimitAreRefusedWithTheBound) {
  const TempDirectory dir("penumbra_limits");
  struct Case {
    const char* pointer;
    json value;
    const char* bound;
  } cases[] = {{"/light/center", {1e30, 4, 0}, "1e+06"},
               {"/light/width", 1e30, "2e+06"},
               {"/camera/position", {1e30, 3, 6}, "1e+06"},
               {"/objects/0/ground/size", 1e30, "2e+06"},
               {"/objects/0/ground/y", -1e7, "1e+06"},
               {"/light/center", {0, 2e6, 0}, "1e+06"}};
  for (const Case& c : cases) {
    json scene = groundAndPlateScene();
    scene[json::json_pointer(c.pointer)] = c.value;
    const std::string message = refusal(dir.write("far.json", scene.dump()));
    EXPECT_TRUE(contains(message, c.pointer)) << message;
    EXPECT_TRUE(contains(message, c.bound)) << c.pointer << ": " << message;
    // Before: a camera at 1e30 was told its up vector was parallel to the view.
    EXPECT_FALSE(contains(message, "parallel")) << message;
  }
  // A glTF scaled past the limit: the assembled scene is checked too.
  const std::string gltf = writeInstancedGltf(dir, "big", 0, 1, 1, 1);
  json scene = groundAndPlateScene();
  scene["objects"].push_back({{"gltf", gltf}, {"scale", 1e9}});
  const std::string message = refusal(dir.write("big.json", scene.dump()));
  EXPECT_TRUE(contains(message, "out of range")) << message;
  EXPECT_TRUE(contains(message, "1e+06")) << message;
}

TEST(SceneLimits, NodeBombIsRefusedByTheSceneBudget) {
  const TempDirectory dir("penumbra_bomb");
  // 10^4 * 11 = 110,000 instances of a one-triangle mesh from a file of a few KiB.
  const std::string instances = writeInstancedGltf(dir, "instances", 4, 10, 11, 1);
  // 10^3 * 10 = 10,000 instances of 600 triangles = 6 M triangles.
  const std::string triangles = writeInstancedGltf(dir, "triangles", 3, 10, 10, 600);
  // The importer counts every instance against the budget as it builds it
  // (app/scene/scene_gltf.cpp), so it stops at the first instance past the budget rather than
  // after building them all; the message names the budget that was passed. No wall-clock
  // bound is asserted: the machine's speed is not what this test is about.
  for (const auto& [path, limit, what] :
       {std::tuple{instances, std::to_string(kMaxSceneObjects), std::string("mesh instances")},
        std::tuple{triangles, std::to_string(kMaxSceneTriangles), std::string("triangles after instancing")}}) {
    const std::string message = refusal(path);
    EXPECT_TRUE(contains(message, "scene budget of " + limit + " " + what)) << message;
  }
}

TEST(SceneLimits, TheBudgetIsPerSceneNotPerFile) {
  const TempDirectory dir("penumbra_budget");
  // 6 * 10^4 = 60,000 instances: one file fits the budget, two do not.
  const std::string half = writeInstancedGltf(dir, "half", 4, 10, 6, 1);
  json one = groundAndPlateScene();
  one["objects"].push_back({{"gltf", half}});
  std::vector<std::string> warnings;
  const Scene loaded = loadScene(dir.write("one.json", one.dump()), warnings);
  EXPECT_EQ(loaded.objects.size(), 60002u);
  json two = one;
  two["objects"].push_back({{"gltf", half}, {"translate", {0, 0, 3}}});
  const std::string message = refusal(dir.write("two.json", two.dump()));
  EXPECT_TRUE(contains(message, "already in the scene")) << message;
  EXPECT_TRUE(contains(message, "/objects/3/gltf")) << message;
}

TEST(SceneLimits, FailedLoadsKeepTheirWarningsAndGltf1IsNamed) {
  const TempDirectory dir("penumbra_messages");
  // Scale 1e-300: every instance singular, so nothing is left; the reason must be shown.
  const std::string tiny = writeInstancedGltf(dir, "tiny", 0, 1, 1, 1, "2.0", 1e-300);
  const std::string message = refusal(tiny);
  EXPECT_TRUE(contains(message, "no triangles")) << message;
  EXPECT_TRUE(contains(message, "singular transform")) << message;
  EXPECT_TRUE(contains(message, "after warning")) << message;
  const std::string old = writeInstancedGltf(dir, "old", 0, 1, 1, 1, "1.0");
  EXPECT_TRUE(contains(refusal(old), "glTF 1.0 is not supported")) << refusal(old);
}

TEST(SceneLimits, HostileKeysAreShortPrintableAndDuplicatesRefused) {
  const TempDirectory dir("penumbra_keys");
  json scene = groundAndPlateScene();
  scene["light"][std::string(10'000'000, 'k')] = 1;
  const std::string huge = refusal(dir.write("huge.json", scene.dump()));
  // The reader's limit on keys (base/json_input.h), the key cut in the pointer.
  EXPECT_TRUE(contains(huge, "/light/kkkk")) << huge.substr(0, 300);
  EXPECT_TRUE(contains(huge, "a key of 9 MiB (at most 4096 bytes)")) << huge.substr(0, 300);
  EXPECT_LT(huge.size(), 1000u) << "the 10 MB key was echoed";
  scene = groundAndPlateScene();
  scene["camera"]["\x1b[31mred\x1b[0m"] = 1;
  const std::string escape = refusal(dir.write("escape.json", scene.dump()));
  EXPECT_EQ(escape.find('\x1b'), std::string::npos) << escape;
  EXPECT_TRUE(contains(escape, "\\x1b[31mred")) << escape;
  // Duplicate keys: JSON parsers keep the last; a scene file refuses them, naming the place.
  const std::string text = groundAndPlateScene().dump();
  const std::string duplicated =
      text.substr(0, text.find("\"width\"")) + "\"width\":2," + text.substr(text.find("\"width\""));
  const std::string twice = refusal(dir.write("twice.json", duplicated));
  EXPECT_TRUE(contains(twice, "/light/width: key given twice")) << twice;
  const std::string nested = R"({"objects": [{"ground": {"size": 1, "size": 2}}], "light": {}, "camera": {}})";
  EXPECT_TRUE(contains(refusal(dir.write("nested.json", nested)), "/objects/0/ground/size: key given twice"));
}

// Case 6: configurations the light's depth maps cannot represent are warned about.
TEST(SceneLimits, LightWarningsNameWhatTheDepthMapsCannotShow) {
  std::vector<std::string> unused;
  for (const char* name : {"cube", "plate", "spheres", "stress_grazing", "stress_contact",
                           "stress_sheet", "stress_light_touching", "stress_far_receiver",
                           "stress_outside_frustum"}) {
    const auto warnings = lightWarnings(loadScene(name, unused));
    EXPECT_TRUE(warnings.empty()) << name << ": " << warnings.front();
  }
  Scene scene = loadScene("cube", unused);
  // Facing away from the occluders (the cube lies below the light, the light faces up).
  scene.light.forward = {0, 1, 0};
  scene.light.up = {0, 0, -1};
  auto warnings = lightWarnings(scene);
  ASSERT_FALSE(warnings.empty());
  EXPECT_TRUE(contains(warnings.front(), "faces away from all geometry")) << warnings.front();
  // Occluders above a light that faces the ground: away from every occluder, not from all.
  scene = loadScene("cube", unused);
  for (SceneObject& object : scene.objects)
    if (!object.receiverOnly) transformMesh(object.mesh, glm::translate(glm::mat4(1), {0, 5, 0}));
  warnings = lightWarnings(scene);
  ASSERT_FALSE(warnings.empty());
  EXPECT_TRUE(contains(warnings.front(), "faces away from every occluder")) << warnings.front();
  EXPECT_TRUE(contains(warnings.front(), "hard_shadow")) << warnings.front();
  // Inside a box larger than the light, and a box the light's rectangle cuts through.
  for (const auto& [size, expected] : {std::pair{3.0f, "sits inside occluder 'box'"},
                                       std::pair{0.5f, "cuts through occluder 'box'"}}) {
    scene = loadScene("cube", unused);
    SceneObject box;
    box.name = "box";
    box.mesh = makeBox(glm::vec3(size), glm::translate(glm::mat4(1), scene.light.center));
    scene.objects.push_back(box);
    warnings = lightWarnings(scene);
    ASSERT_EQ(warnings.size(), 1u) << size;
    EXPECT_TRUE(contains(warnings.front(), expected)) << warnings.front();
  }
  // A light at the height of the ground: in its plane (facing down) or cut by it (facing
  // sideways). The reference's mean visibility was 0.248 there, the trace's 0.933, SSM's
  // 1.000, and nothing said why.
  for (const glm::vec3 forward : {glm::vec3(0, -1, 0), glm::vec3(1, 0, 0)}) {
    scene = loadScene("cube", unused);
    float groundY = 1e30f;
    for (const SceneObject& object : scene.objects)
      if (object.receiverOnly)
        for (const glm::vec3& p : object.mesh.positions) groundY = std::min(groundY, p.y);
    scene.light.center.y = groundY;
    scene.light.forward = forward;
    scene.light.up = forward.y != 0 ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
    warnings = lightWarnings(scene);
    bool named = false;
    for (const std::string& warning : warnings)
      named = named || contains(warning, "lies in or cuts through the plane of receiver");
    EXPECT_TRUE(named) << forward.x << " " << (warnings.empty() ? "no warning" : warnings.front());
  }
}

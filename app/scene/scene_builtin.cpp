#include "scene/scene_builtin.h"

#include "base/input_error.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <stdexcept>

#include "scene/mesh_builders.h"
#include "scene/scene_animated.h"
#include "scene/scene_file.h"
#include "scene/scene_frame.h"
#include "scene/scene_gltf.h"
#include "scene/scene_stress.h"

namespace {

const char* kEnginePath =
    "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";

// The models shipped in assets/models (with their acknowledgement); $PENUMBRA_ASSET_DIR moves them.
std::filesystem::path assetPath(const std::string& name) {
  if (const char* override = std::getenv("PENUMBRA_ASSET_DIR")) return std::filesystem::path(override) / name;
  return std::filesystem::path(PENUMBRA_SOURCE_DIR) / "assets" / name;
}

SceneObject ground(float size = 12.0f) {
  return {"ground", makeQuad(size, glm::mat4(1)), glm::vec3(0.85f), true};
}

// The thesis's elongated cube (Fig 4.2): a long box hovering over the ground, its long axis
// across the light, so the shadow beneath darkens with the box's thickness (§4).
Scene cube() {
  Scene scene;
  scene.name = "cube";
  scene.objects.push_back(ground());
  glm::mat4 place = glm::translate(glm::mat4(1), {0, 0.9f, 0});
  place = glm::rotate(place, glm::radians(30.0f), {0, 1, 0});
  scene.objects.push_back({"elongated cube", makeBox({2.4f, 0.5f, 0.5f}, place),
                           {0.9f, 0.35f, 0.25f}, false});
  scene.light = {{0.6f, 4.0f, 0.3f}, glm::normalize(glm::vec3(-0.15f, -1, -0.05f)), {0, 0, -1},
                 1.6f, 1.6f};
  scene.camera = {{0.5f, 3.6f, 5.6f}, {0, 0.3f, 0}, {0, 1, 0}, 45};
  return scene;
}

// A zero-thickness square parallel to the light and the ground: visibility is analytic.
Scene plate() {
  Scene scene;
  scene.name = "plate";
  scene.objects.push_back(ground());
  scene.objects.push_back(
      {"plate", makeQuad(1.0f, glm::translate(glm::mat4(1), {0, 1, 0})), {0.3f, 0.5f, 0.9f}, false});
  scene.light = {{0, 3, 0}, {0, -1, 0}, {0, 0, -1}, 1.0f, 1.0f};
  scene.camera = {{0, 3.5f, 4.5f}, {0, 0.2f, 0}, {0, 1, 0}, 45};
  return scene;
}

Scene spheres() {
  Scene scene;
  scene.name = "spheres";
  scene.objects.push_back(ground());
  scene.objects.push_back({"sphere on ground", makeSphere({-1.0f, 0.5f, 0.3f}, 0.5f),
                           {0.9f, 0.3f, 0.3f}, false});
  scene.objects.push_back({"sphere mid", makeSphere({0.4f, 1.0f, -0.2f}, 0.35f),
                           {0.3f, 0.8f, 0.4f}, false});
  scene.objects.push_back({"sphere high", makeSphere({1.1f, 1.8f, 0.6f}, 0.25f),
                           {0.3f, 0.4f, 0.9f}, false});
  scene.light = {{0.2f, 4.0f, 0.5f}, {0, -1, 0}, {0, 0, -1}, 1.5f, 1.5f};
  scene.camera = {{0, 3.4f, 5.5f}, {0, 0.5f, 0}, {0, 1, 0}, 45};
  return scene;
}

// Puts loaded objects on the ground: scaled so the largest side is `size`, resting on y = 0.
// Returns the scale applied.
float placeOnGround(std::vector<SceneObject>& objects, float size, Bounds* fileBounds = nullptr,
                    glm::mat4* placed = nullptr) {
  Bounds bounds;
  for (const SceneObject& object : objects)
    for (const glm::vec3& p : object.mesh.positions) bounds.extend(p);
  if (fileBounds) *fileBounds = bounds;
  const glm::vec3 extent = bounds.max - bounds.min;
  const float scale = size / std::max({extent.x, extent.y, extent.z, 1e-6f});
  const glm::vec3 center = 0.5f * (bounds.min + bounds.max);
  glm::mat4 place = glm::scale(glm::mat4(1), glm::vec3(scale));
  place = glm::translate(place, {-center.x, -bounds.min.y, -center.z});
  for (SceneObject& object : objects) transformMesh(object.mesh, place);
  if (placed) *placed = place;
  return scale;
}

// A researcher's bare glTF, in whatever units it was written: scaled to 2.5 units across on
// the ground (the size every stage's defaults are set for: depth bias, light size, map
// resolution), then the camera, ground and light framed around it. The file's own bounds
// and the scale go into the scene's notes.
Scene bareGltf(const std::string& path, std::vector<std::string>& warnings) {
  Scene scene;
  scene.name = std::filesystem::path(path).stem().string();
  GltfAnimation animation;
  std::vector<SceneObject> loaded = loadGltf(path, glm::mat4(1), warnings, nullptr, &animation);
  Bounds fileBounds;
  glm::mat4 place(1);
  const float scale = placeOnGround(loaded, 2.5f, &fileBounds, &place);
  // The file's node animation, moved with the model onto the ground, after the ground.
  for (ObjectMotion& motion : animation.motions) {
    placeMotion(motion, glm::dmat4(place));
    for (size_t& object : motion.objects) object += 1;
    scene.animation.objects.push_back(std::move(motion));
  }
  scene.animation.duration = scene.animation.endTime();
  char factor[32];
  std::snprintf(factor, sizeof factor, "%.4g", scale);
  scene.notes.push_back(std::filesystem::path(path).filename().string() + " in file units: " +
                        boundsText(fileBounds) + ", scaled by " + factor +
                        " to 2.5 across on the ground");
  scene.objects.push_back(ground());
  for (SceneObject& object : loaded) scene.objects.push_back(std::move(object));
  frameScene(scene);
  return scene;
}

Scene gltfOnGround(const std::string& path, const std::string& name,
                   std::vector<std::string>& warnings) {
  Scene scene;
  scene.name = name;
  std::vector<SceneObject> loaded = loadGltf(path, glm::mat4(1), warnings);
  placeOnGround(loaded, 2.5f);
  scene.objects.push_back(ground());
  for (SceneObject& object : loaded) scene.objects.push_back(std::move(object));
  scene.light = {{0.5f, 5.0f, 0.5f}, glm::normalize(glm::vec3(-0.1f, -1, -0.1f)), {0, 0, -1},
                 1.5f, 1.5f};
  scene.camera = {{2.5f, 3.5f, 5.0f}, {0, 0.7f, 0}, {0, 1, 0}, 45};
  return scene;
}

// Thesis Figure 4.1 / 1.1(a): the Stanford dragon (91,216 triangles; the thesis's had 100,000)
// on a floor, a wall behind it. The light stands in front of the dragon and above it, so the
// dragon casts sharp contact shadows at its feet and a broad shadow on the far wall; the horn
// and the tail shadow the body (the self-shadowing of Figure 3.5). Floor and wall only receive.
Scene dragon(std::vector<std::string>& warnings) {
  Scene scene;
  scene.name = "dragon";
  std::vector<SceneObject> loaded =
      loadGltf(assetPath("models/dragon.glb").string(), glm::mat4(1), warnings);
  placeOnGround(loaded, 2.5f);
  scene.objects.push_back(ground());
  glm::mat4 wallPlace = glm::translate(glm::mat4(1), {0, 0, -1.4f});
  wallPlace = glm::rotate(wallPlace, glm::radians(90.0f), {1, 0, 0});
  scene.objects.push_back({"wall", makeQuad(12.0f, wallPlace), glm::vec3(0.8f), true});
  for (SceneObject& object : loaded) scene.objects.push_back(std::move(object));
  const glm::vec3 lightCenter{-2.2f, 3.2f, 2.6f}, lightAim{0.4f, 0.5f, -1.2f};
  scene.light = {lightCenter, glm::normalize(lightAim - lightCenter), {0, 1, 0}, 1.5f, 1.5f};
  scene.camera = {{1.6f, 2.0f, 5.4f}, {0.2f, 0.8f, -0.5f}, {0, 1, 0}, 45};
  return scene;
}

}  // namespace

std::vector<std::string> builtinSceneNames() {
  std::vector<std::string> names = {"cube", "plate", "spheres", "engine", "dragon"};
  for (const std::string& animated : animatedSceneNames()) names.push_back(animated);
  return names;
}

bool isBuiltinScene(const std::string& name) {
  const auto names = builtinSceneNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

Scene makeBuiltinScene(const std::string& name) {
  std::vector<std::string> warnings;
  if (name == "cube") return cube();
  if (name == "plate") return plate();
  if (name == "spheres") return spheres();
  if (name == "engine") return gltfOnGround(kEnginePath, "engine", warnings);
  if (name == "dragon") return dragon(warnings);
  if (isAnimatedScene(name)) return makeAnimatedScene(name, warnings);
  std::string valid;
  for (const std::string& each : builtinSceneNames()) valid += (valid.empty() ? "" : ", ") + each;
  throw InputError("unknown scene '" + printable(name, 200) + "'; built-in scenes: " + valid +
                           " (stress scenes: stress_grazing, stress_contact, ...), or a path to "
                           "a .json, .gltf or .glb file");
}

namespace {

Scene loadSceneOrThrow(const std::string& nameOrPath, std::vector<std::string>& warnings) {
  Scene scene;
  const std::string extension = std::filesystem::path(nameOrPath).extension().string();
  if (isStressScene(nameOrPath))
    scene = makeStressScene(nameOrPath);
  else if (isBuiltinScene(nameOrPath))
    scene = nameOrPath == "engine"   ? gltfOnGround(kEnginePath, "engine", warnings)
            : nameOrPath == "dragon"   ? dragon(warnings)
            : isAnimatedScene(nameOrPath) ? makeAnimatedScene(nameOrPath, warnings)
                                          : makeBuiltinScene(nameOrPath);
  else if (extension == ".json") {
    scene = loadSceneFile(nameOrPath, warnings);
    for (std::string& warning : cameraWarnings(scene)) warnings.push_back(std::move(warning));
  } else if (extension == ".gltf" || extension == ".glb")
    scene = bareGltf(nameOrPath, warnings);
  else
    scene = makeBuiltinScene(nameOrPath);  // throws with the list of valid names
  std::string problem = validateScene(scene);
  if (problem.empty() && !scene.animation.empty()) problem = posedSceneProblem(scene, 0);
  if (!problem.empty()) throw InputError(printable(nameOrPath, 200) + ": " + problem);
  return scene;
}

}  // namespace

Scene loadScene(const std::string& nameOrPath, std::vector<std::string>& warnings) {
  const size_t before = warnings.size();
  try {
    return loadSceneOrThrow(nameOrPath, warnings);
  } catch (const InputError& error) {
    // The warnings often say why (a singular transform skipped every mesh): keep them.
    std::string message = error.what();
    for (size_t i = before; i < warnings.size(); ++i) message += "\n  after warning: " + warnings[i];
    throw InputError(message);
  }
}

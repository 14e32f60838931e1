#include "scene/scene_stress.h"

#include "base/input_error.h"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

#include "scene/mesh_builders.h"

namespace {

SceneObject ground(float size = 12.0f, float y = 0.0f) {
  return {"ground", makeQuad(size, glm::translate(glm::mat4(1), {0, y, 0})), glm::vec3(0.85f), true};
}

SceneObject box(const char* name, glm::vec3 size, glm::vec3 center) {
  return {name, makeBox(size, glm::translate(glm::mat4(1), center)), {0.8f, 0.4f, 0.3f}, false};
}

Scene base(const std::string& name) {
  Scene scene;
  scene.name = name;
  scene.objects.push_back(ground());
  scene.light = {{0, 4, 0}, {0, -1, 0}, {0, 0, -1}, 1.5f, 1.5f};
  scene.camera = {{0, 3.5f, 5.0f}, {0, 0.3f, 0}, {0, 1, 0}, 45};
  return scene;
}

}  // namespace

std::vector<std::string> stressSceneNames() {
  return {"stress_grazing", "stress_contact", "stress_sheet", "stress_light_touching",
          "stress_far_receiver", "stress_outside_frustum"};
}

bool isStressScene(const std::string& name) {
  const auto names = stressSceneNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

Scene makeStressScene(const std::string& name) {
  Scene scene = base(name);
  if (name == "stress_grazing") {
    // The light skims the ground: n.l -> 0 everywhere on the receiver (Eq 3.2's clamp).
    scene.objects.push_back(box("box", {0.6f, 0.6f, 0.6f}, {0, 0.3f, 0}));
    scene.light = {{-6, 0.35f, 0}, glm::normalize(glm::vec3(1, -0.02f, 0)), {0, 1, 0}, 0.6f, 0.3f};
  } else if (name == "stress_contact") {
    // An occluder resting on the receiver: contact shadows, receiver depth == occluder depth.
    scene.objects.push_back(box("box on ground", {1, 0.5f, 1}, {0, 0.25f, 0}));
  } else if (name == "stress_sheet") {
    // A zero-thickness sheet, tilted: near == far over its whole extent.
    scene.objects.push_back({"sheet",
                             makeQuad(1.2f, glm::rotate(glm::translate(glm::mat4(1), {0, 1, 0}),
                                                        glm::radians(25.0f), {1, 0, 0})),
                             {0.3f, 0.6f, 0.9f}, false});
  } else if (name == "stress_light_touching") {
    // The light almost touches the occluder: Eq 3.3's z_near_min -> n.
    scene.objects.push_back(box("box", {0.8f, 0.8f, 0.8f}, {0, 3.595f, 0}));
    scene.light.center = {0, 4.0f, 0};
  } else if (name == "stress_far_receiver") {
    // The receiver lies far behind a small occluder: depth precision over a long range.
    scene.objects[0] = ground(4000.0f, -500.0f);
    scene.objects.push_back(box("box", {0.5f, 0.5f, 0.5f}, {0, 2.5f, 0}));
    scene.camera = {{0, 5, 8}, {0, -200, -400}, {0, 1, 0}, 50};
  } else if (name == "stress_outside_frustum") {
    // Occluders and receivers partly outside the light's frustum (a narrow fov reaches less).
    scene.objects.push_back(box("inside", {0.8f, 0.8f, 0.8f}, {0, 1, 0}));
    scene.objects.push_back(box("outside", {0.8f, 0.8f, 0.8f}, {5.5f, 1, 0}));
    scene.camera = {{3, 5, 9}, {2, 0, 0}, {0, 1, 0}, 50};
  } else {
    std::string valid;
    for (const std::string& each : stressSceneNames()) valid += (valid.empty() ? "" : ", ") + each;
    throw InputError("unknown stress scene '" + name + "'; valid: " + valid);
  }
  return scene;
}

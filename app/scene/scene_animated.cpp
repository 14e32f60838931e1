#include "scene/scene_animated.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

#include "base/input_error.h"
#include "scene/mesh_builders.h"
#include "scene/scene_builtin.h"

namespace {

glm::dquat eulerDegrees(double x, double y, double z) {
  return glm::angleAxis(glm::radians(z), glm::dvec3(0, 0, 1)) *
         glm::angleAxis(glm::radians(y), glm::dvec3(0, 1, 0)) *
         glm::angleAxis(glm::radians(x), glm::dvec3(1, 0, 0));
}

// A TRS about `pivot` for `objects` (the scene file's object animation).
ObjectMotion aboutPivot(std::vector<size_t> objects, const glm::dvec3& pivot, TrsTrack trs) {
  ObjectMotion motion;
  motion.objects = std::move(objects);
  ChainLink to, move, back;
  to.fixed = glm::translate(glm::dmat4(1), pivot);
  move.animated = true;
  move.trs = std::move(trs);
  back.fixed = glm::translate(glm::dmat4(1), -pivot);
  motion.chain = {to, move, back};
  return motion;
}

// A full turn about y in `seconds`: keys every quarter turn (each 90 degrees, under the
// 180 at which slerp would take the other way round).
QuatTrack fullTurn(double seconds) {
  QuatTrack track;
  for (int k = 0; k <= 4; ++k) {
    track.times.push_back(seconds * k / 4);
    track.values.push_back(eulerDegrees(0, 90.0 * k, 0));
  }
  return track;
}

Scene dragonTurntable(std::vector<std::string>& warnings) {
  Scene scene = loadScene("dragon", warnings);
  scene.name = "dragon_turntable";
  // The dragon's objects (everything but the floor and the wall) turn about the vertical
  // through the centre of their bounds.
  std::vector<size_t> dragon;
  Bounds bounds;
  for (size_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].name != "ground" && scene.objects[i].name != "wall") {
      dragon.push_back(i);
      for (const glm::vec3& p : scene.objects[i].mesh.positions) bounds.extend(p);
    }
  const glm::dvec3 pivot(0.5 * (bounds.min.x + bounds.max.x), 0, 0.5 * (bounds.min.z + bounds.max.z));
  // Room to turn: the wall moved back behind the dragon's turning radius.
  double radius = 0;
  for (size_t i : dragon)
    for (const glm::vec3& p : scene.objects[i].mesh.positions)
      radius = std::max(radius, glm::length(glm::dvec2(p.x - pivot.x, p.z - pivot.z)));
  for (SceneObject& object : scene.objects)
    if (object.name == "wall") {
      const float wallZ = object.mesh.positions[0].z;
      const float wantZ = static_cast<float>(pivot.z - radius - 0.1);
      if (wantZ < wallZ)
        transformMesh(object.mesh, glm::translate(glm::mat4(1), {0, 0, wantZ - wallZ}));
    }
  TrsTrack trs;
  trs.rotationKeys = fullTurn(8);
  scene.animation.objects.push_back(aboutPivot(dragon, pivot, trs));
  scene.animation.duration = 8;
  scene.animation.repeat = Repeat::Loop;
  return scene;
}

Scene lightSweep() {
  Scene scene = makeBuiltinScene("cube");
  scene.name = "light_sweep";
  LightMotion& light = scene.animation.light;
  light.center.times = {0, 3};
  light.center.values = {{-1.8, 4.0, 0.3}, {2.2, 4.0, 0.3}};
  // Tilted towards the box as it passes: 20 degrees one way, 20 the other.
  light.orientation.times = {0, 3};
  light.orientation.values = {eulerDegrees(0, 0, 20), eulerDegrees(0, 0, -20)};
  light.width.times = {0, 3};
  light.width.values = {0.4, 2.4};
  light.height = light.width;
  scene.light.center = {-1.8f, 4.0f, 0.3f};
  scene.light.width = scene.light.height = 0.4f;
  scene.animation.duration = 3;
  scene.animation.repeat = Repeat::PingPong;
  return scene;
}

Scene toys() {
  Scene scene;
  scene.name = "toys";
  scene.objects.push_back({"ground", makeQuad(12.0f, glm::mat4(1)), glm::vec3(0.85f), true});
  // A long box spinning on the spot, once every 4 s.
  scene.objects.push_back({"spinning box",
                           makeBox({1.1f, 0.6f, 0.5f}, glm::translate(glm::mat4(1), {-1.2f, 0.3f, 0})),
                           {0.9f, 0.35f, 0.25f}, false});
  TrsTrack spin;
  spin.rotationKeys = fullTurn(4);
  scene.animation.objects.push_back(aboutPivot({1}, {-1.2, 0.3, 0}, spin));
  // A ball bouncing: up 1.2 and down again twice in 4 s (it touches the ground at the ends).
  scene.objects.push_back({"bouncing ball", makeSphere({0.3f, 0.35f, 0.6f}, 0.35f),
                           {0.3f, 0.8f, 0.4f}, false});
  TrsTrack bounce;
  bounce.translationKeys.times = {0, 0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4};
  for (double t : bounce.translationKeys.times) {
    const double phase = std::fmod(t, 2.0) - 1.0;  // -1 .. 1 per bounce
    bounce.translationKeys.values.push_back({0, 1.2 * (1 - phase * phase), 0});
  }
  scene.animation.objects.push_back(aboutPivot({2}, {0.3, 0.35, 0.6}, bounce));
  // A small ball circling the scene at 1.6 high, radius 1.3, once every 4 s.
  scene.objects.push_back({"circling ball", makeSphere({1.3f, 1.6f, 0}, 0.22f),
                           {0.3f, 0.4f, 0.9f}, false});
  TrsTrack circle;
  for (int k = 0; k <= 16; ++k) {
    const double angle = 2 * M_PI * k / 16;
    circle.translationKeys.times.push_back(4.0 * k / 16);
    circle.translationKeys.values.push_back(
        {1.3 * std::cos(angle) - 1.3, 0, -1.3 * std::sin(angle)});
  }
  scene.animation.objects.push_back(aboutPivot({3}, {1.3, 1.6, 0}, circle));
  // A plank rocking 25 degrees either way about its long axis, on a post.
  scene.objects.push_back({"post", makeBox({0.1f, 0.6f, 0.1f}, glm::translate(glm::mat4(1), {0.9f, 0.3f, -1.0f})),
                           glm::vec3(0.6f), false});
  scene.objects.push_back({"rocking plank",
                           makeBox({1.4f, 0.06f, 0.4f}, glm::translate(glm::mat4(1), {0.9f, 0.63f, -1.0f})),
                           {0.9f, 0.8f, 0.3f}, false});
  TrsTrack rock;
  rock.rotationKeys.times = {0, 1, 2, 3, 4};
  for (double z : {0.0, 25.0, 0.0, -25.0, 0.0}) rock.rotationKeys.values.push_back(eulerDegrees(0, 0, z));
  scene.animation.objects.push_back(aboutPivot({5}, {0.9, 0.63, -1.0}, rock));
  scene.light = {{0.4f, 4.2f, 0.6f}, glm::normalize(glm::vec3(-0.1f, -1, -0.1f)), {0, 0, -1}, 1.4f, 1.4f};
  scene.camera = {{0.4f, 3.8f, 5.6f}, {0, 0.5f, 0}, {0, 1, 0}, 45};
  scene.animation.duration = 4;
  scene.animation.repeat = Repeat::Loop;
  return scene;
}

// A slowly moving occluder, for temporal aliasing (thesis §4.1: "at much lower resolutions
// temporal aliasing becomes a problem"): a square plate 1 high under a 1 x 1 light 3 above
// it slides 0.25 along x and turns 5 degrees about the vertical in 4 s, and back. At 24
// frames a second it moves 0.0026 a frame: 1/24 of a 128^2 map's texel at the plate (the
// light's 90-degree frustum is about 6 wide there), so its rasterized outline, and every
// depth-map method's shadow with it, stands still for frames and then jumps a texel.
Scene slowSlide() {
  Scene scene;
  scene.name = "slow_slide";
  scene.objects.push_back({"ground", makeQuad(8.0f, glm::mat4(1)), glm::vec3(0.85f), true});
  scene.objects.push_back({"plate",
                           makeBox({1.0f, 0.04f, 0.7f}, glm::rotate(glm::translate(glm::mat4(1), {-0.1f, 1.0f, 0}),
                                                                   glm::radians(20.0f), {0, 1, 0})),
                           {0.3f, 0.5f, 0.9f}, false});
  TrsTrack slide;
  slide.translationKeys.times = {0, 4};
  slide.translationKeys.values = {{0, 0, 0}, {0.25, 0, 0}};
  slide.rotationKeys.times = {0, 4};
  slide.rotationKeys.values = {eulerDegrees(0, 0, 0), eulerDegrees(0, 5, 0)};
  scene.animation.objects.push_back(aboutPivot({1}, {-0.1, 1.0, 0}, slide));
  scene.light = {{0, 4.0f, 0}, {0, -1, 0}, {0, 0, -1}, 1.0f, 1.0f};
  scene.camera = {{0, 3.2f, 3.4f}, {0, 0.2f, 0}, {0, 1, 0}, 45};
  scene.animation.duration = 4;
  scene.animation.repeat = Repeat::PingPong;
  return scene;
}

}  // namespace

std::vector<std::string> animatedSceneNames() { return {"dragon_turntable", "light_sweep", "toys", "slow_slide"}; }

bool isAnimatedScene(const std::string& name) {
  const auto names = animatedSceneNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

Scene makeAnimatedScene(const std::string& name, std::vector<std::string>& warnings) {
  if (name == "dragon_turntable") return dragonTurntable(warnings);
  if (name == "light_sweep") return lightSweep();
  if (name == "toys") return toys();
  if (name == "slow_slide") return slowSlide();
  throw InputError("unknown animated scene '" + printable(name, 200) + "'");
}

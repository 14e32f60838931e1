#include "scene/scene_file.h"

#include "scene/mesh_builders.h"

#include "base/input_error.h"
#include "base/json_input.h"
#include "scene/scene_gltf.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <set>
#include <sstream>
#include <stdexcept>

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// RFC 6901 escaping, bounded, control characters escaped (base/json_input.h).
std::string pointerTo(const std::string& parent, const std::string& key) {
  return jsonPointer(parent, key);
}

std::string typeOf(const json& value) {
  const std::string type = value.type_name();
  return (type == "object" || type == "array" ? "an " : "a ") + type;
}

class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}

  std::string message(const std::string& pointer, const std::string& what) const {
    return path_ + ": " + (pointer.empty() ? "/" : pointer) + ": " + what;
  }
  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const {
    throw InputError(message(pointer, what));
  }

  // Objects must be objects and hold only known keys: a misspelt key is an error.
  void expectObject(const json& value, const std::string& pointer,
                    std::initializer_list<const char*> valid) const {
    if (!value.is_object()) fail(pointer, "expected an object, got " + typeOf(value));
    for (const auto& [key, unused] : value.items()) {
      bool known = false;
      std::string list;
      for (const char* name : valid) {
        known = known || key == name;
        list += (list.empty() ? "" : ", ") + std::string(name);
      }
      if (!known) fail(pointer, "unknown key '" + printable(key) + "' (valid keys: " + list + ")");
    }
  }

  const json& required(const json& object, const std::string& pointer, const char* key) const {
    if (!object.contains(key)) fail(pointerTo(pointer, key), "missing (required)");
    return object[key];
  }

  double number(const json& value, const std::string& pointer) const {
    if (!value.is_number()) fail(pointer, "expected a number, got " + typeOf(value));
    const double result = value.get<double>();
    // nlohmann refuses literals such as 1e999 itself; values beyond float range (or
    // close enough that arithmetic overflows) would turn into infinities later.
    if (!std::isfinite(result) || std::abs(result) > 1e30)
      fail(pointer, "must be finite and within +-1e30, got " + value.dump());
    return result;
  }

  double positive(const json& value, const std::string& pointer) const {
    const double result = number(value, pointer);
    if (!(result > 0)) fail(pointer, "must be positive, got " + value.dump());
    return result;
  }

  glm::vec3 vec3(const json& value, const std::string& pointer) const {
    if (!value.is_array() || value.size() != 3)
      fail(pointer,
           "expected an array of 3 numbers, got " +
               (value.is_array() ? "an array of " + std::to_string(value.size()) : typeOf(value)));
    return {number(value[0], pointer + "/0"), number(value[1], pointer + "/1"),
            number(value[2], pointer + "/2")};
  }

  // A position: within the scene limit (app/scene/scene.h) every back end can represent.
  glm::vec3 point(const json& value, const std::string& pointer) const {
    // The scene limit first, so that 1e308 is told the limit that applies (+-1e6).
    if (value.is_array() && value.size() == 3)
      for (size_t i = 0; i < 3; ++i)
        if (value[i].is_number()) limited(value[i].get<double>(), pointer + "/" + std::to_string(i), kMaxCoordinate);
    return vec3(value, pointer);
  }
  double bounded(const json& value, const std::string& pointer, double bound) const {
    if (value.is_number()) limited(value.get<double>(), pointer, bound);
    return number(value, pointer);
  }
  double limited(double v, const std::string& pointer, double bound) const {
    if (std::abs(v) > bound) {
      std::ostringstream text;
      text << "must be within +-" << bound << " (the scene limit: the GPU computes in single "
           << "precision and Embree rejects larger rays; scale the scene down), got " << v;
      fail(pointer, text.str());
    }
    return v;
  }

  std::string string(const json& value, const std::string& pointer) const {
    if (!value.is_string()) fail(pointer, "expected a string, got " + typeOf(value));
    return value.get<std::string>();
  }

  bool boolean(const json& value, const std::string& pointer) const {
    if (!value.is_boolean()) fail(pointer, "expected true or false, got " + typeOf(value));
    return value.get<bool>();
  }

  glm::vec3 color(const json& value, const std::string& pointer) const {
    const glm::vec3 c = vec3(value, pointer);
    for (int i = 0; i < 3; ++i)
      if (c[i] < 0 || c[i] > 1) fail(pointer + "/" + std::to_string(i), "must be in [0, 1]");
    return c;
  }

 private:
  std::string path_;
};

// T * Rz * Ry * Rx * S: the model is scaled, rotated about X then Y then Z (world axes),
// then moved.
glm::mat4 placement(const Reader& r, const json& object, const std::string& pointer) {
  glm::vec3 translate(0), rotate(0), scale(1);
  if (object.contains("translate")) translate = r.point(object["translate"], pointer + "/translate");
  if (object.contains("rotate_degrees"))
    rotate = r.vec3(object["rotate_degrees"], pointer + "/rotate_degrees");
  if (object.contains("scale")) {
    const json& s = object["scale"];
    const std::string at = pointer + "/scale";
    scale = s.is_number() ? glm::vec3(static_cast<float>(r.number(s, at))) : r.vec3(s, at);
    for (int i = 0; i < 3; ++i)
      if (!(scale[i] > 0))
        r.fail(at, "must be positive (a number or an array of 3 positive numbers)");
  }
  glm::mat4 m = glm::translate(glm::mat4(1), translate);
  m = glm::rotate(m, glm::radians(rotate.z), {0, 0, 1});
  m = glm::rotate(m, glm::radians(rotate.y), {0, 1, 0});
  m = glm::rotate(m, glm::radians(rotate.x), {1, 0, 0});
  return glm::scale(m, scale);
}

// The rotation of rotate_degrees (x, y, z): about X, then Y, then Z (world axes), as the
// placement above.
glm::dquat eulerDegrees(const glm::dvec3& degrees) {
  const glm::dvec3 r = glm::radians(degrees);
  return glm::angleAxis(r.z, glm::dvec3(0, 0, 1)) * glm::angleAxis(r.y, glm::dvec3(0, 1, 0)) *
         glm::angleAxis(r.x, glm::dvec3(1, 0, 0));
}

// {"times": [t0, t1, ...], "values": [v0, v1, ...], "interpolation": "linear" | "step"}:
// times finite, not negative, strictly increasing; one value per time, each read by `value`
// (which names its own pointer in a refusal).
template <class T, class ReadValue>
Track<T> readTrack(const Reader& r, const json& track, const std::string& at, ReadValue value) {
  r.expectObject(track, at, {"times", "values", "interpolation"});
  Track<T> result;
  const json& times = r.required(track, at, "times");
  const std::string timesAt = at + "/times";
  if (!times.is_array() || times.empty())
    r.fail(timesAt, "expected a non-empty array of times (seconds), got " + typeOf(times));
  for (size_t i = 0; i < times.size(); ++i) {
    const std::string keyAt = timesAt + "/" + std::to_string(i);
    const double time = r.number(times[i], keyAt);
    if (time < 0) r.fail(keyAt, "must not be negative, got " + times[i].dump());
    if (i > 0 && !(time > result.times.back()))
      r.fail(keyAt, "times must increase: " + times[i].dump() + " is not after " +
                        times[i - 1].dump());
    result.times.push_back(time);
  }
  const json& values = r.required(track, at, "values");
  const std::string valuesAt = at + "/values";
  if (!values.is_array())
    r.fail(valuesAt, "expected an array of values, got " + typeOf(values));
  if (values.size() != times.size())
    r.fail(valuesAt, std::to_string(values.size()) + " values for " +
                         std::to_string(times.size()) + " times (one value per time)");
  for (size_t i = 0; i < values.size(); ++i)
    result.values.push_back(value(values[i], valuesAt + "/" + std::to_string(i)));
  if (track.contains("interpolation")) {
    const std::string mode = r.string(track["interpolation"], at + "/interpolation");
    if (mode == "linear" || mode == "LINEAR")
      result.interpolation = Interpolation::Linear;
    else if (mode == "step" || mode == "STEP")
      result.interpolation = Interpolation::Step;
    else
      r.fail(at + "/interpolation", "unknown interpolation '" + printable(mode) +
                                        "' (valid: linear, step)");
  }
  return result;
}

glm::dvec3 positiveScale(const Reader& r, const json& s, const std::string& at) {
  const glm::dvec3 scale = s.is_number() ? glm::dvec3(r.number(s, at)) : glm::dvec3(r.vec3(s, at));
  for (int i = 0; i < 3; ++i)
    if (!(scale[i] > 0)) r.fail(at, "must be positive (a number or an array of 3 positive numbers)");
  return scale;
}

// An object's "animation": a TRS about `pivot` (default: the centre of the object's rest
// bounds), on top of its placement: translate(pivot + translate(t)) R(t) S(t) translate(-pivot).
ObjectMotion readObjectMotion(const Reader& r, const json& animation, const std::string& at,
                              const Scene& scene, size_t first) {
  r.expectObject(animation, at, {"pivot", "translate", "rotate_degrees", "scale"});
  Bounds rest;
  for (size_t i = first; i < scene.objects.size(); ++i)
    for (const glm::vec3& p : scene.objects[i].mesh.positions) rest.extend(p);
  glm::dvec3 pivot = rest.empty() ? glm::dvec3(0) : 0.5 * (glm::dvec3(rest.min) + glm::dvec3(rest.max));
  if (animation.contains("pivot")) pivot = r.point(animation["pivot"], at + "/pivot");
  ChainLink trs;
  trs.animated = true;
  if (animation.contains("translate"))
    trs.trs.translationKeys = readTrack<glm::dvec3>(
        r, animation["translate"], at + "/translate",
        [&](const json& v, const std::string& p) { return glm::dvec3(r.point(v, p)); });
  if (animation.contains("rotate_degrees"))
    trs.trs.rotationKeys = readTrack<glm::dquat>(
        r, animation["rotate_degrees"], at + "/rotate_degrees",
        [&](const json& v, const std::string& p) { return eulerDegrees(r.vec3(v, p)); });
  if (animation.contains("scale"))
    trs.trs.scaleKeys = readTrack<glm::dvec3>(
        r, animation["scale"], at + "/scale",
        [&](const json& v, const std::string& p) { return positiveScale(r, v, p); });
  ObjectMotion motion;
  for (size_t i = first; i < scene.objects.size(); ++i) motion.objects.push_back(i);
  ChainLink toPivot, fromPivot;
  toPivot.fixed = glm::translate(glm::dmat4(1), pivot);
  fromPivot.fixed = glm::translate(glm::dmat4(1), -pivot);
  motion.chain = {toPivot, trs, fromPivot};
  return motion;
}

LightMotion readLightMotion(const Reader& r, const json& animation, const std::string& at) {
  r.expectObject(animation, at, {"center", "rotate_degrees", "width", "height"});
  LightMotion motion;
  if (animation.contains("center"))
    motion.center = readTrack<glm::dvec3>(
        r, animation["center"], at + "/center",
        [&](const json& v, const std::string& p) { return glm::dvec3(r.point(v, p)); });
  if (animation.contains("rotate_degrees"))
    motion.orientation = readTrack<glm::dquat>(
        r, animation["rotate_degrees"], at + "/rotate_degrees",
        [&](const json& v, const std::string& p) { return eulerDegrees(r.vec3(v, p)); });
  auto size = [&](const json& v, const std::string& p) {
    r.bounded(v, p, 2 * kMaxCoordinate);
    return r.positive(v, p);
  };
  if (animation.contains("width"))
    motion.width = readTrack<double>(r, animation["width"], at + "/width", size);
  if (animation.contains("height"))
    motion.height = readTrack<double>(r, animation["height"], at + "/height", size);
  return motion;
}

void readObject(const Reader& r, const json& object, const std::string& pointer,
                const fs::path& baseDir, Scene& scene, std::vector<std::string>& warnings,
                SceneBudget& budget) {
  if (!object.is_object()) r.fail(pointer, "expected an object, got " + typeOf(object));
  const bool isGltf = object.contains("gltf"), isGround = object.contains("ground");
  if (isGltf == isGround) r.fail(pointer, "needs exactly one of 'gltf' or 'ground'");
  std::string name;
  if (object.contains("name")) name = r.string(object["name"], pointer + "/name");
  const size_t first = scene.objects.size();

  if (isGround) {
    r.expectObject(object, pointer, {"ground", "name", "color", "receiver_only", "animation"});
    const std::string at = pointer + "/ground";
    r.expectObject(object["ground"], at, {"size", "y"});
    r.bounded(r.required(object["ground"], at, "size"), at + "/size", 2 * kMaxCoordinate);
    const float size = static_cast<float>(r.positive(object["ground"]["size"], at + "/size"));
    const float y = object["ground"].contains("y")
                        ? static_cast<float>(r.bounded(object["ground"]["y"], at + "/y", kMaxCoordinate))
                        : 0.0f;
    SceneObject ground;
    ground.name = name.empty() ? "ground" : name;
    ground.mesh = makeQuad(size, glm::translate(glm::mat4(1), {0, y, 0}));
    ground.receiverOnly = true;  // a floor rarely shadows anything; saves a depth layer
    if (budget.objects < 1 || budget.triangles < ground.mesh.triangleCount())
      r.fail(pointer, "more than the scene budget of " + std::to_string(kMaxSceneObjects) +
                          " objects");
    budget.objects -= 1;
    budget.triangles -= ground.mesh.triangleCount();
    scene.objects.push_back(std::move(ground));
  } else {
    r.expectObject(
        object, pointer,
        {"gltf", "name", "translate", "rotate_degrees", "scale", "color", "receiver_only",
         "animation"});
    const std::string at = pointer + "/gltf";
    const std::string file = r.string(object["gltf"], at);
    if (file.empty()) r.fail(at, "empty path");
    fs::path modelPath(file);
    if (modelPath.is_relative()) modelPath = (baseDir / modelPath).lexically_normal();
    const glm::mat4 world = placement(r, object, pointer);
    std::vector<SceneObject> loaded;
    GltfAnimation fileAnimation;
    try {
      loaded = loadGltf(modelPath.string(), world, warnings, &budget, &fileAnimation);
    } catch (const std::exception& e) {
      r.fail(at, e.what());
    }
    // The file's own node animation plays first, then the object's "animation" (below).
    for (ObjectMotion& motion : fileAnimation.motions) {
      for (size_t& index : motion.objects) index += first;
      scene.animation.objects.push_back(std::move(motion));
    }
    for (SceneObject& o : loaded) {
      if (!name.empty()) o.name = name + "/" + o.name;
      scene.objects.push_back(std::move(o));
    }
  }

  for (size_t i = first; i < scene.objects.size(); ++i) {
    SceneObject& o = scene.objects[i];
    if (object.contains("color")) o.baseColor = r.color(object["color"], pointer + "/color");
    if (object.contains("receiver_only"))
      o.receiverOnly = r.boolean(object["receiver_only"], pointer + "/receiver_only");
  }
  if (object.contains("animation"))
    scene.animation.objects.push_back(
        readObjectMotion(r, object["animation"], pointer + "/animation", scene, first));
}

AreaLight readLight(const Reader& r, const json& root, std::vector<std::string>& warnings,
                    LightMotion& motion) {
  const json& light = r.required(root, "", "light");
  const std::string at = "/light";
  r.expectObject(light, at, {"center", "forward", "up", "width", "height", "animation"});
  if (light.contains("animation")) motion = readLightMotion(r, light["animation"], at + "/animation");
  AreaLight result;
  result.center = r.point(r.required(light, at, "center"), at + "/center");
  // Directions in double: no overflow for any finite input.
  glm::dvec3 forward = r.vec3(r.required(light, at, "forward"), at + "/forward");
  glm::dvec3 up = r.vec3(r.required(light, at, "up"), at + "/up");
  r.bounded(r.required(light, at, "width"), at + "/width", 2 * kMaxCoordinate);
  r.bounded(r.required(light, at, "height"), at + "/height", 2 * kMaxCoordinate);
  result.width = static_cast<float>(r.positive(light["width"], at + "/width"));
  result.height = static_cast<float>(r.positive(light["height"], at + "/height"));
  if (glm::length(forward) < 1e-6) r.fail(at + "/forward", "must not be zero");
  if (glm::length(up) < 1e-6) r.fail(at + "/up", "must not be zero");
  forward = glm::normalize(forward);
  up = glm::normalize(up);
  // Consumers build the light's frame from these two; give them an orthonormal pair.
  const double cosine = glm::dot(forward, up);
  if (std::abs(cosine) > 0.999) r.fail(at + "/up", "is parallel to forward");
  if (std::abs(cosine) > 1e-3)
    warnings.push_back(
        r.message(at + "/up", "not perpendicular to forward; using its perpendicular part"));
  result.forward = glm::vec3(forward);
  result.up = glm::vec3(glm::normalize(up - cosine * forward));
  return result;
}

Camera readCamera(const Reader& r, const json& root) {
  const json& camera = r.required(root, "", "camera");
  const std::string at = "/camera";
  r.expectObject(camera, at, {"position", "target", "up", "fov_y_degrees"});
  Camera result;
  result.position = r.point(r.required(camera, at, "position"), at + "/position");
  result.target = r.point(r.required(camera, at, "target"), at + "/target");
  if (camera.contains("up")) result.up = r.vec3(camera["up"], at + "/up");
  if (camera.contains("fov_y_degrees")) {
    result.fovYDegrees =
        static_cast<float>(r.number(camera["fov_y_degrees"], at + "/fov_y_degrees"));
    if (!(result.fovYDegrees > 1 && result.fovYDegrees < 179))
      r.fail(at + "/fov_y_degrees", "must be in (1, 179)");
  }
  // In double: no overflow for any finite input.
  const glm::dvec3 view = glm::dvec3(result.target) - glm::dvec3(result.position);
  const glm::dvec3 up(result.up);
  if (glm::length(view) < 1e-6) r.fail(at + "/target", "must differ from position");
  if (glm::length(up) < 1e-6 || glm::length(glm::cross(glm::normalize(view), glm::normalize(up))) < 1e-3)
    r.fail(at + "/up", "must be non-zero and not parallel to the view direction");
  return result;
}

// "animation": {"duration": seconds, "repeat": "loop" | "ping_pong" | "once"}; the duration
// defaults to the last key of any track (the file's glTF animations included).
void readAnimationTiming(const Reader& r, const json& root, Animation& animation) {
  animation.duration = animation.endTime();
  if (!root.contains("animation")) return;
  const json& timing = root["animation"];
  r.expectObject(timing, "/animation", {"duration", "repeat"});
  if (timing.contains("duration")) {
    r.bounded(timing["duration"], "/animation/duration", 1e6);
    animation.duration = r.positive(timing["duration"], "/animation/duration");
  }
  if (timing.contains("repeat")) {
    const std::string repeat = r.string(timing["repeat"], "/animation/repeat");
    if (repeat == "loop")
      animation.repeat = Repeat::Loop;
    else if (repeat == "ping_pong")
      animation.repeat = Repeat::PingPong;
    else if (repeat == "once")
      animation.repeat = Repeat::Once;
    else
      r.fail("/animation/repeat",
             "unknown repeat '" + printable(repeat) + "' (valid: loop, ping_pong, once)");
  }
}

}  // namespace

Scene loadSceneFile(const std::string& path, std::vector<std::string>& warnings) {
  // A regular file of bounded size (a FIFO or a device is refused before reading).
  return parseSceneFile(readInputFile(path), path, warnings);
}

Scene parseSceneFile(const std::string& text, const std::string& path,
                     std::vector<std::string>& warnings) {
  const Reader r(path);
  // The limits every JSON input shares: depth, size, string length, repeated keys.
  const json root = parseJsonText(text, path);
  r.expectObject(root, "", {"name", "objects", "light", "camera", "animation"});

  Scene scene;
  scene.name =
      root.contains("name") ? r.string(root["name"], "/name") : fs::path(path).stem().string();
  const json& objects = r.required(root, "", "objects");
  if (!objects.is_array() || objects.empty())
    r.fail("/objects", "expected a non-empty array of objects");
  const fs::path baseDir = fs::path(path).parent_path();
  SceneBudget budget;  // shared by every object of the file
  for (size_t i = 0; i < objects.size(); ++i)
    readObject(r, objects[i], "/objects/" + std::to_string(i), baseDir, scene, warnings, budget);
  scene.light = readLight(r, root, warnings, scene.animation.light);
  scene.camera = readCamera(r, root);
  readAnimationTiming(r, root, scene.animation);

  std::string problem = validateScene(scene);
  if (problem.empty() && !scene.animation.empty()) problem = posedSceneProblem(scene, 0);
  if (!problem.empty()) throw InputError(path + ": " + problem);
  return scene;
}

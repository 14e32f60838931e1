#include "window/script/ui_settings.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "base/input_error.h"
#include "io/image_export.h"
#include "base/json_input.h"
#include "io/output_path.h"
#include "scene/scene_builtin.h"
#include "window/script/ui_settings_views.h"
#include "window/ui_state.h"

using nlohmann::json;

namespace {

json vec3Json(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }

// A problem found while reading; thrown to stop at the first one.
struct SettingsError {
  std::string message;
};

void fail(const std::string& pointer, const std::string& what) {
  throw SettingsError{(pointer.empty() ? "/" : pointer) + ": " + what};
}

double number(const json& value, const std::string& pointer) {
  if (!value.is_number() || !std::isfinite(value.get<double>())) fail(pointer, "expected a finite number");
  return value.get<double>();
}

glm::vec3 vec3(const json& value, const std::string& pointer) {
  if (!value.is_array() || value.size() != 3) fail(pointer, "expected [x, y, z]");
  return {float(number(value[0], pointer + "/0")), float(number(value[1], pointer + "/1")),
          float(number(value[2], pointer + "/2"))};
}

void onlyKeys(const json& object, const std::string& pointer, std::initializer_list<const char*> keys) {
  if (!object.is_object()) fail(pointer, "expected an object");
  for (const auto& [key, value] : object.items()) {
    bool known = false;
    std::string valid;
    for (const char* allowed : keys) {
      known = known || key == allowed;
      valid += (valid.empty() ? "" : ", ") + std::string(allowed);
    }
    if (!known) fail(jsonPointer(pointer, key), "unknown key; valid: " + valid);
  }
}

// A JSON parameter value as the text Param::set parses (doubles with every digit).
std::string parameterText(const json& value, const std::string& pointer) {
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_integer()) return std::to_string(value.get<long long>());
  if (value.is_number()) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value.get<double>());
    return text;
  }
  fail(pointer, "expected a number, boolean or string");
  return "";
}

}  // namespace

// 1. Everything a user can change in the window.
json settingsJson(const UiState& state) {
  json root;
  root["penumbra_settings"] = 1;
  root["scene"] = state.session.sceneSource;
  root["time"] = state.session.time;  // seconds into the scene's animation
  root["eye"] = state.session.eye.fitView ? json("fit") : json::array({state.session.eye.width, state.session.eye.height});
  const Camera& camera = state.session.scene.camera;
  root["camera"] = {{"position", vec3Json(camera.position)}, {"target", vec3Json(camera.target)},
                    {"up", vec3Json(camera.up)}, {"fov_y_degrees", camera.fovYDegrees}};
  const AreaLight& light = state.session.scene.light;
  root["light"] = {{"center", vec3Json(light.center)}, {"forward", vec3Json(light.forward)},
                   {"up", vec3Json(light.up)}, {"width", light.width}, {"height", light.height}};
  json parameters = json::object();
  for (const auto& stage : state.session.pipeline.stages())
    for (const Param& param : stage->params()) {
      const std::string key = stage->name() + "." + param.key;
      if (param.automatic) {
        parameters[key] = "auto";
        continue;
      }
      switch (param.type) {
        case Param::Type::Bool: parameters[key] = param.asBool(); break;
        case Param::Type::Int: parameters[key] = param.asInt(); break;
        case Param::Type::Float: parameters[key] = param.value; break;
        case Param::Type::Enum: parameters[key] = param.asEnum(); break;
      }
    }
  root["parameters"] = parameters;
  root["ui_scale"] = uiScaleJson(state);
  root["views"] = viewsJson(state);
  return root;
}

// 2. Read and check into copies; commit only when all of it is valid.
std::string applySettingsJson(UiState& state, const json& root) {
  try {
    onlyKeys(root, "", {"penumbra_settings", "scene", "eye", "camera", "light", "parameters", "ui_scale", "views", "time"});
    // 2a. Parameters, checked on copies of the declarations.
    std::vector<std::pair<Param*, Param>> parameters;
    if (root.contains("parameters")) {
      if (!root["parameters"].is_object()) fail("/parameters", "expected an object");
      for (const auto& [key, value] : root["parameters"].items()) {
        const std::string pointer = jsonPointer("/parameters", key);
        Param* declared = nullptr;
        try {
          declared = &state.session.pipeline.param(key);
        } catch (const std::out_of_range& error) {
          fail(pointer, error.what());
        }
        Param copy = *declared;
        if (std::string problem = copy.set(parameterText(value, pointer)); !problem.empty())
          fail(pointer, problem);
        parameters.emplace_back(declared, copy);
      }
    }
    // 2b. Eye size, camera, light.
    EyeSize eye = state.session.eye;
    if (root.contains("eye")) {
      const json& value = root["eye"];
      if (value == "fit") eye.fitView = true;
      else if (value.is_array() && value.size() == 2 && value[0].is_number_integer() &&
               value[1].is_number_integer() && value[0] >= 16 && value[1] >= 16 &&
               value[0] <= 8192 && value[1] <= 8192)
        eye = {false, value[0].get<int>(), value[1].get<int>()};
      else fail("/eye", "expected \"fit\" or [width, height] in [16, 8192]");
    }
    std::string scene = state.session.sceneSource;
    if (root.contains("scene")) {
      if (!root["scene"].is_string()) fail("/scene", "expected a scene name or path");
      scene = root["scene"].get<std::string>();
    }
    std::optional<Scene> loaded;  // a new scene is adopted only if everything else is valid
    if (scene != state.session.sceneSource) {
      std::vector<std::string> warnings;
      try {
        loaded = loadScene(scene, warnings);
      } catch (const std::exception& error) {
        fail("/scene", error.what());
      }
    }
    Scene candidate = loaded ? *loaded : state.session.scene;
    if (root.contains("camera")) {
      const json& c = root["camera"];
      onlyKeys(c, "/camera", {"position", "target", "up", "fov_y_degrees"});
      Camera& camera = candidate.camera;
      if (c.contains("position")) camera.position = vec3(c["position"], "/camera/position");
      if (c.contains("target")) camera.target = vec3(c["target"], "/camera/target");
      if (c.contains("up")) camera.up = vec3(c["up"], "/camera/up");
      if (c.contains("fov_y_degrees")) camera.fovYDegrees = float(number(c["fov_y_degrees"], "/camera/fov_y_degrees"));
    }
    if (root.contains("light")) {
      const json& l = root["light"];
      onlyKeys(l, "/light", {"center", "forward", "up", "width", "height"});
      AreaLight& light = candidate.light;
      if (l.contains("center")) light.center = vec3(l["center"], "/light/center");
      // As given (computeLightFrame orthonormalises); validateScene rejects parallel ones.
      if (l.contains("forward")) light.forward = vec3(l["forward"], "/light/forward");
      if (l.contains("up")) light.up = vec3(l["up"], "/light/up");
      if (l.contains("width")) light.width = float(number(l["width"], "/light/width"));
      if (l.contains("height")) light.height = float(number(l["height"], "/light/height"));
    }
    if (std::string problem = validateScene(candidate); !problem.empty()) fail("", problem);
    std::optional<double> time;
    if (root.contains("time")) {
      time = number(root["time"], "/time");
      if (std::abs(*time) > 1e9) fail("/time", "must be within +-1e9 seconds");
    }
    // 2c. UI scale and views (checked whole, applied last).
    std::vector<std::function<void(UiState&)>> interface;
    try {
      if (root.contains("ui_scale")) interface.push_back(readUiScale(state, root["ui_scale"], "/ui_scale"));
      if (root.contains("views")) interface.push_back(readViews(state, root["views"], "/views"));
    } catch (const std::invalid_argument& error) {
      throw SettingsError{error.what()};
    }
    // 2d. Commit.
    if (loaded) state.adoptScene(std::move(*loaded), scene);
    state.session.scene.camera = candidate.camera;
    state.session.scene.light = candidate.light;
    state.session.eye = eye;
    for (auto& [declared, value] : parameters) *declared = value;
    for (const auto& apply : interface) apply(state);
    if (time) return state.session.setTime(*time);
    return "";
  } catch (const SettingsError& error) {
    return error.message;
  }
}

// 3. Files (written atomically, like every export). An existing file is replaced only when
// it is a settings file itself (it holds "penumbra_settings"): the output rule
// (io/output_path.h) for a single file a user may have named by mistake.
std::string saveSettingsFile(const UiState& state, const std::string& path) {
  try {
    const std::filesystem::path target(path);
    checkOutputFile(target, "settings file");
    std::error_code error;
    if (std::filesystem::exists(target, error)) {
      bool settings = false;
      try {
        settings = readJsonFile(path).contains("penumbra_settings");
      } catch (const std::exception&) {
      }
      if (!settings)
        return "saving settings refused: '" + printable(path, 200) +
               "' exists and is not a penumbra settings file (no \"penumbra_settings\"); "
               "it is left alone: choose another name";
    }
    if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path());
    writeTextFile(target, settingsJson(state).dump(2) + "\n");
    return "saved settings to " + std::filesystem::absolute(target).string();
  } catch (const std::exception& error) {
    return std::string("saving settings failed: ") + error.what();
  }
}

// The reader rule every JSON input shares (base/json_input.h): a regular file (a FIFO is
// refused, never waited on), bounded depth, size and strings, no repeated key.
std::string loadSettingsFile(UiState& state, const std::string& path, bool& ok) {
  ok = false;
  json root;
  try {
    root = readJsonFile(path);
  } catch (const InputError& error) {
    return std::string("settings file ") + error.what();
  }
  if (std::string problem = applySettingsJson(state, root); !problem.empty())
    return printable(path, 200) + ": " + problem;
  ok = true;
  return "loaded settings from " + std::filesystem::absolute(path).string();
}

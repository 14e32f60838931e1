#include "core/pipeline.h"

#include <chrono>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

Stage& Pipeline::stage(const std::string& name) const {
  for (const auto& stage : stages_)
    if (stage->name() == name) return *stage;
  std::string valid;
  for (const auto& stage : stages_) valid += (valid.empty() ? "" : ", ") + stage->name();
  throw std::out_of_range("unknown stage '" + name + "'; valid: " + valid);
}

std::vector<std::string> Pipeline::paramKeys() const {
  std::vector<std::string> keys;
  for (const auto& stage : stages_)
    for (const Param& param : stage->params()) keys.push_back(stage->name() + "." + param.key);
  return keys;
}

Param& Pipeline::param(const std::string& stageDotKey) const {
  const size_t dot = stageDotKey.find('.');
  if (dot != std::string::npos) {
    for (const auto& stage : stages_)
      if (stage->name() == stageDotKey.substr(0, dot))
        for (Param& param : stage->params())
          if (param.key == stageDotKey.substr(dot + 1)) return param;
  }
  std::string valid;
  for (const std::string& key : paramKeys()) valid += (valid.empty() ? "" : ", ") + key;
  throw std::out_of_range("unknown parameter '" + stageDotKey + "'; valid keys: " + valid);
}

std::string Pipeline::set(const std::string& assignment) {
  const size_t equals = assignment.find('=');
  if (equals == std::string::npos)
    return "'" + assignment + "' is not of the form stage.key=value";
  try {
    const std::string key = assignment.substr(0, equals);
    const std::string problem = param(key).set(assignment.substr(equals + 1));
    return problem.empty() ? "" : key + ": " + problem;
  } catch (const std::out_of_range& error) {
    return error.what();
  }
}

void Pipeline::prepare(Frame& frame) const {
  const Scene& scene = frame.scene;
  frame.light = computeLightFrame(scene.light, scene.bounds(),
                                  param("light_layers.fov_degrees").asFloat());
  const int layerSize = param("light_layers.resolution").asInt();

  gpu::FrameUniforms& u = frame.uniforms;
  const float aspect = float(frame.eyeWidth) / float(frame.eyeHeight);
  const Bounds bounds = scene.bounds();
  const float sceneSize = bounds.empty() ? 10.0f : glm::length(bounds.max - bounds.min);
  const float distance = glm::length(scene.camera.target - scene.camera.position);
  const float eyeNear = std::max(1e-3f * sceneSize, 0.02f * distance);
  const float eyeFar = distance + 2.0f * sceneSize;
  const glm::mat4 viewFromWorld =
      glm::lookAt(scene.camera.position, scene.camera.target, scene.camera.up);
  const glm::mat4 clipFromView =
      glm::perspective(glm::radians(scene.camera.fovYDegrees), aspect, eyeNear, eyeFar);
  u.clipFromWorld = clipFromView * viewFromWorld;
  u.worldFromClip = glm::inverse(u.clipFromWorld);
  u.lightClipFromWorld = frame.light.lightClipFromWorld;
  u.lightViewFromWorld = frame.light.lightViewFromWorld;
  u.wsEyePosition = glm::vec4(scene.camera.position, 1);
  u.wsLightCenter = glm::vec4(scene.light.center, scene.light.width * scene.light.height);
  u.wsLightRight = glm::vec4(frame.light.right, 0.5f * scene.light.width);
  u.wsLightUp = glm::vec4(frame.light.up, 0.5f * scene.light.height);
  u.wsLightForward = glm::vec4(frame.light.forward, frame.light.lightDepth);
  u.lightDepthRange = glm::vec4(frame.light.zNear, frame.light.zFar, frame.light.tanHalfFovX,
                                frame.light.tanHalfFovY);
  u.sizes = glm::uvec4(frame.eyeWidth, frame.eyeHeight, layerSize, layerSize);
  u.shading = glm::vec4(param("composite.ambient").asFloat(), 0, 0, 0);
  u.keys = glm::uvec4(frame.frameKey, 0, 0, 0);
  frame.uniformBuffer.upload(&u, sizeof u);
  glBindBufferBase(GL_UNIFORM_BUFFER, binding::kFrameUniforms, frame.uniformBuffer.id());
}

void Pipeline::run(Frame& frame) {
  prepare(frame);
  frame.counters.clear();
  times_.clear();
  glFinish();
  for (const auto& stage : stages_) {
    const auto start = std::chrono::steady_clock::now();
    stage->run(frame);
    glFinish();
    const std::chrono::duration<double, std::milli> elapsed =
        std::chrono::steady_clock::now() - start;
    times_.push_back({stage->name(), elapsed.count()});
  }
}

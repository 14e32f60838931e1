#include "export/trace_json.h"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/pipeline.h"
#include "monte_carlo/trace/trace_steps.h"
#include "shared_inputs/light/auto_params.h"

const char* stepDecisionName(int decision) {
  static const char* names[] = {"descend", "advance", "ascend", "hit", "miss",
                                "early_out_backface", "early_out_inside", "early_out_region",
                                "sample", "refine", "eye_visible", "classified"};
  return decision >= 0 && decision < int(std::size(names)) ? names[decision] : "unknown";
}

std::string traceStepsJson(const Frame& frame, int x, int y) {
  nlohmann::json result;
  result["pixel"] = {x, y};
  result["image_size"] = {frame.eyeWidth, frame.eyeHeight};
  const GlTexture& visibility = frame.texture("trace.visibility");
  const int glY = frame.eyeHeight - 1 - y;
  float value = 0;
  glGetTextureSubImage(visibility.id(), 0, x, glY, 0, 1, 1, 1, GL_RED, GL_FLOAT, sizeof value,
                       &value);
  result["visibility"] = value;
  const int raysPerSide = effectiveRays(frame.pipeline.param("trace.rays"), lightAutoSettings(frame));
  result["rays"] = raysPerSide * raysPerSide;
  result["search"] = frame.pipeline.param("trace.search").asEnum();
  result["layers"] = effectiveLayers(frame.pipeline.param("light.layers"), lightAutoSettings(frame));
  nlohmann::json steps = nlohmann::json::array();
  for (const gpu::TraceStep& step : recordedTraceSteps(frame))
    steps.push_back({{"ray", step.header.x},
                     {"level", step.header.y},
                     {"decision", stepDecisionName(step.header.z)},
                     {"iteration", step.header.w},
                     {"window", {step.window.x, step.window.y, step.window.z, step.window.w}},
                     {"zNearMin", step.depths.x},
                     {"zFarMax", step.depths.y},
                     {"rayDepthIn", step.depths.z},
                     {"rayDepthOut", step.depths.w},
                     {"steppingBefore", step.stepping.x},
                     {"steppingAfter", step.stepping.y},
                     {"texelPoint", {step.stepping.z, step.stepping.w}}});
  result["steps"] = steps;
  return result.dump(1) + "\n";
}

namespace {

// Single quotes for a POSIX shell where the text needs them.
std::string shellWord(const std::string& text) {
  const bool plain = !text.empty() && text.find_first_not_of(
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-+=.,/:@%") == std::string::npos;
  if (plain) return text;
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

std::string traceCommandLine(const std::string& scene, int x, int y, int width, int height,
                             const std::vector<std::string>& sets, double time) {
  std::string command = "penumbra trace --scene " + shellWord(scene) + " --pixel " +
                        std::to_string(x) + "," + std::to_string(y) + " --width " +
                        std::to_string(width) + " --height " + std::to_string(height);
  for (const std::string& set : sets) command += " --set " + shellWord(set);
  if (time != 0) {
    char seconds[40];
    std::snprintf(seconds, sizeof seconds, " --time %.17g", time);
    command += seconds;
  }
  return command;
}

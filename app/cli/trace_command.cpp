#include "cli/trace_command.h"

#include "core/auto_params.h"

#include <cstdio>
#include <nlohmann/json.hpp>

#include <filesystem>

#include "io/headless_session.h"
#include "io/image_export.h"
#include "io/output_path.h"

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
  const int raysPerSide = effectiveRays(frame.pipeline.param("trace.rays"), frame.autoSettings);
  result["rays"] = raysPerSide * raysPerSide;
  result["search"] = frame.pipeline.param("trace.search").asEnum();
  result["layers"] = effectiveLayers(frame.pipeline.param("light.layers"), frame.autoSettings);
  nlohmann::json steps = nlohmann::json::array();
  for (const gpu::TraceStep& step : frame.traceSteps)
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

int runTraceCommand(const TraceOptions& options) {
  int x = -1, y = -1;
  char extra = 0;
  if (std::sscanf(options.pixel.c_str(), "%d,%d%c", &x, &y, &extra) != 2 || x < 0 || y < 0 ||
      x >= options.width || y >= options.height) {
    std::fprintf(stderr, "penumbra trace: --pixel '%s' must be X,Y inside the %dx%d image\n",
                 options.pixel.c_str(), options.width, options.height);
    return 2;
  }
  if (!options.out.empty()) checkOutputFile(options.out, "--out");  // before any rendering
  std::vector<std::string> sets = options.sets;
  sets.push_back("trace.record_x=" + std::to_string(x));
  sets.push_back("trace.record_y=" + std::to_string(y));
  HeadlessSession session;
  if (int status = session.open("trace", options.scene, sets, options.width, options.height,
                                options.time))
    return status;
  session.pipeline.run(*session.frame);
  const std::string json = traceStepsJson(*session.frame, x, y);
  if (options.out.empty()) {
    std::fputs(json.c_str(), stdout);
    return 0;
  }
  const std::filesystem::path out(options.out);
  if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
  writeTextFile(out, json);
  std::printf("penumbra trace: %zu steps written to %s\n", session.frame->traceSteps.size(),
              options.out.c_str());
  return 0;
}

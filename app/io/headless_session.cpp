#include "io/headless_session.h"

#include <cmath>
#include <cstdio>

#include "base/input_error.h"
#include "io/renderer_calibration_measure.h"

#include "scene/scene_builtin.h"
#include "scene/scene_checks.h"
#include "scene/scene_frame.h"

std::string disabledSelection(const Pipeline& pipeline, const std::vector<std::string>& sets) {
  const auto named = [&](const std::string& key) {
    for (const std::string& assignment : sets)
      if (assignment.rfind(key + "=", 0) == 0) return true;
    return false;
  };
  for (const auto& stage : pipeline.stages())
    for (const Param& param : stage->params()) {
      if (param.type != Param::Type::Enum || param.automatic) continue;
      const std::string key = stage->name() + "." + param.key, chosen = param.asEnum();
      for (const auto& target : pipeline.stages()) {
        if (target->name() != chosen) continue;
        for (const Param& enabled : target->params())
          if (enabled.key == "enabled" && enabled.type == Param::Type::Bool && !enabled.asBool() &&
              (named(key) || named(chosen + ".enabled")))
            return key + "=" + chosen + " selects " + chosen + ", which is disabled (" + chosen +
                   ".enabled=false): it does not run, so " + key + " would use nothing and the "
                   "result would silently lack it; add --set " + chosen + ".enabled=true";
      }
    }
  return "";
}

int HeadlessSession::open(const std::string& command, const std::string& sceneNameOrPath,
                          const std::vector<std::string>& sets, int width, int height,
                          double time) {
  const auto fail = [&](int status, const std::string& message) {
    std::fprintf(stderr, "penumbra %s: %s\n", command.c_str(), message.c_str());
    return status;
  };
  // 1. Input first, so bad input fails fast without touching OpenGL.
  std::vector<std::string> warnings;
  try {
    const Scene rest = loadScene(sceneNameOrPath, warnings);
    if (!std::isfinite(time) || std::abs(time) > 1e9)
      return fail(2, "--time must be finite and within +-1e9 seconds");
    if (std::string problem = posedSceneProblem(rest, time); !problem.empty())
      return fail(2, printable(sceneNameOrPath, 200) + ": " + problem);
    scene = poseAt(rest, time);
    if (!rest.animation.empty())
      std::fprintf(stderr, "penumbra %s: scene '%s' posed at time %g s (%g s into its %g s %s)\n",
                   command.c_str(), printable(scene.name).c_str(), time,
                   rest.animation.cycleTime(time), rest.animation.duration,
                   repeatName(rest.animation.repeat));
  } catch (const std::exception& error) {
    return fail(2, error.what());
  }
  std::fprintf(stderr, "penumbra %s: scene '%s': %s\n", command.c_str(), scene.name.c_str(),
               sceneSummary(scene).c_str());
  for (const std::string& warning : warnings) std::fprintf(stderr, "warning: %s\n", warning.c_str());
  for (const std::string& warning : lightWarnings(scene))
    std::fprintf(stderr, "warning: %s\n", warning.c_str());
  for (const std::string& assignment : sets)
    if (std::string problem = pipeline.set(assignment); !problem.empty())
      return fail(2, "--set " + problem);
  // Refused rather than warned: the output would be silently wrong (a composite without the
  // selected shadow, an error stage measuring nothing), and the fix is one more --set.
  if (std::string problem = disabledSelection(pipeline, sets); !problem.empty()) return fail(2, "--set " + problem);
  // 2. OpenGL, the scene on the GPU, the frame.
  std::string error;
  context = GlContext::createHeadless(error);
  if (!context) return fail(1, error);
  // `auto` per renderer: this context's calibration (gl/renderer_calibration.h).
  if (int status = applyRendererCalibration(command); status != 0) return status;
  gpuScene = std::make_unique<GpuScene>(scene);
  frame = std::make_unique<Frame>(scene, *gpuScene, pipeline);
  frame->eyeWidth = width;
  frame->eyeHeight = height;
  return 0;
}

#include "io/headless_session.h"

#include <cstdio>

#include "scene/scene_builtin.h"
#include "scene/scene_checks.h"
#include "scene/scene_frame.h"

int HeadlessSession::open(const std::string& command, const std::string& sceneNameOrPath,
                          const std::vector<std::string>& sets, int width, int height) {
  const auto fail = [&](int status, const std::string& message) {
    std::fprintf(stderr, "penumbra %s: %s\n", command.c_str(), message.c_str());
    return status;
  };
  // 1. Input first, so bad input fails fast without touching OpenGL.
  std::vector<std::string> warnings;
  try {
    scene = loadScene(sceneNameOrPath, warnings);
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
  // 2. OpenGL, the scene on the GPU, the frame.
  std::string error;
  context = GlContext::createHeadless(error);
  if (!context) return fail(1, error);
  gpuScene = std::make_unique<GpuScene>(scene);
  frame = std::make_unique<Frame>(scene, *gpuScene, pipeline);
  frame->eyeWidth = width;
  frame->eyeHeight = height;
  return 0;
}

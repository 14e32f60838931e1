#include "gl_test.h"

#include <cstdlib>

GlContext& headlessContext() {
  static std::unique_ptr<GlContext> context = [] {
    // `auto` with the constants unless a test asks otherwise (as CTest sets it): outputs that do
    // not depend on the machine's load (docs/decisions/071-auto-calibrated-per-renderer.md).
    setenv("PENUMBRA_CALIBRATION", "fallback", /*overwrite=*/0);
    std::string error;
    auto created = GlContext::createHeadless(error);
    if (!created) {
      std::fprintf(stderr, "headless context: %s\n", error.c_str());
      std::abort();
    }
    // Any GL error (KHR_debug, GL_DEBUG_TYPE_ERROR) fails the test that caused it.
    setGlErrorHook([](const char* message) { ADD_FAILURE() << "GL error: " << message; });
    return created;
  }();
  return *context;
}

PipelineRun::PipelineRun(Scene sceneIn, const std::vector<std::string>& sets, int width,
                         int height)
    : scene(std::move(sceneIn)) {
  headlessContext();
  gpuScene = std::make_unique<GpuScene>(scene);
  pipeline = std::make_unique<Pipeline>();
  for (const std::string& assignment : sets) {
    const std::string problem = pipeline->set(assignment);
    EXPECT_EQ(problem, "") << assignment;
  }
  frame = std::make_unique<Frame>(scene, *gpuScene, *pipeline);
  frame->eyeWidth = width;
  frame->eyeHeight = height;
  run();
}

// What every headless command starts with: the scene loaded and validated, the `--set`
// assignments applied, a headless GL context, the scene on the GPU and one frame.
// Failures print "penumbra <command>: <what is wrong>" and give the exit status: 2 for bad
// input (scene, --set), 1 for a missing OpenGL 4.5.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/frame.h"
#include "gl/gl_context.h"
#include "core/pipeline.h"

// A selection the user made that names a disabled stage: "composite.shadow=raster4d" while
// raster4d.enabled is false shades with no shadow at all, "error.method=raster4d" or
// "error.against=reference" with that stage off measures nothing. Only choices named in
// `sets` (or whose stage's "enabled" is named there) count: the defaults (error.against =
// reference, reference off) ask for nothing. "" or the message naming the fix.
std::string disabledSelection(const Pipeline& pipeline, const std::vector<std::string>& sets);

class HeadlessSession {
public:
  // Returns 0 when ready, else the exit status (the message is printed).
  // The scene is posed at `time` (seconds, scene/animation.h); a pose that fails
  // validateScene() is bad input.
  int open(const std::string& command, const std::string& sceneNameOrPath,
           const std::vector<std::string>& sets, int width, int height, double time = 0);

  // The context first: members die in reverse order, so every GL object dies before it.
  std::unique_ptr<GlContext> context;
  Scene scene;  // posed at the time given to open()
  Pipeline pipeline;
  std::unique_ptr<GpuScene> gpuScene;
  std::unique_ptr<Frame> frame;
};

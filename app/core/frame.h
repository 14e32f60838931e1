// Everything one run of the pipeline reads and writes: the scene on the GPU, the per-frame
// uniforms, and every stage output by name ("stage.output").
#pragma once
#include <chrono>
#include <map>
#include <memory>
#include <string>

#include "gl/gl_texture.h"
#include "gl/gpu_layout_trace.h"
#include "gl/gpu_scene.h"
#include "scene/light_frame.h"
#include "core/stage.h"

class Pipeline;

struct Frame {
  const Scene& scene;
  const GpuScene& gpuScene;
  const Pipeline& pipeline;  // for reading another stage's parameters
  int eyeWidth = 512, eyeHeight = 512;
  std::uint32_t frameKey = 0;  // scrambles the hash per frame (thesis Appendix A "key")
  LightFrame light{};
  gpu::FrameUniforms uniforms{};
  GlBuffer uniformBuffer;

  std::map<std::string, GlTexture> textures;  // "stage.output"
  std::map<std::string, double> counters;     // "trace.rays", ...
  std::vector<gpu::TraceStep> traceSteps;     // every step of the recorded pixel's rays
  // Storage buffers one stage hands to a later one ("classify.tracedPixels"); not exported.
  std::map<std::string, std::unique_ptr<GlBuffer>> buffers;
  GlBuffer& buffer(const std::string& name) {
    auto& slot = buffers[name];
    if (!slot) slot = std::make_unique<GlBuffer>();
    return *slot;
  }

  Frame(const Scene& scene, const GpuScene& gpuScene, const Pipeline& pipeline)
      : scene(scene), gpuScene(gpuScene), pipeline(pipeline) {}

  // Allocates (or reuses, when the shape matches) the texture of a declared output.
  GlTexture& output(const Stage& stage, const std::string& name, int width, int height,
                    int layers = 0);
  // A texture written earlier in the frame; throws naming what is missing.
  const GlTexture& input(const std::string& stageDotOutput) const;
  bool has(const std::string& stageDotOutput) const { return textures.count(stageDotOutput) > 0; }
};

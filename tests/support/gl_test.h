// Test support: one headless GL 4.5 context per test binary, and a pipeline run on a scene.
#pragma once
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "core/frame.h"
#include "gl/gl_context.h"
#include "core/pipeline.h"
#include "scene/scene.h"

// The process-wide headless context (created on first use; the test fails if it cannot be).
// Every GL error reported through KHR_debug while a test runs fails that test.
GlContext& headlessContext();

// A scene, its GPU copy, a pipeline with `sets` applied and one frame, run once.
struct PipelineRun {
  Scene scene;
  std::unique_ptr<GpuScene> gpuScene;
  std::unique_ptr<Pipeline> pipeline;
  std::unique_ptr<Frame> frame;
  PipelineRun(Scene scene, const std::vector<std::string>& sets, int width = 256,
              int height = 256);
  void run() { pipeline->run(*frame); }
  std::vector<float> read(const std::string& stageDotOutput, int layer = 0) const {
    return frame->texture(stageDotOutput).readFloats(layer);
  }
};

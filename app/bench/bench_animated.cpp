#include "bench/bench_animated.h"

#include <chrono>
#include <cstdio>
#include <memory>

#include "core/frame.h"
#include "core/pipeline.h"
#include "gl/gpu_scene.h"

std::vector<double> timeLoop(Pipeline& pipeline, const ParamSnapshot& defaults,
                             const std::vector<std::string>& sets, const BenchSetup& setup,
                             const std::vector<BenchResult>& results, std::vector<FrameTimes>& times) {
  std::vector<double> poseMs;
  for (size_t i = 0; i < setup.loopTimes.size(); ++i) {
    const double t = setup.loopTimes[i];
    // 1. The pose and its upload (glFinish: the upload is done when the clock stops).
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    const Scene posed = poseAt(*setup.rest, t);
    const auto gpuScene = std::make_unique<GpuScene>(posed);
    glFinish();
    poseMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    Frame frame(posed, *gpuScene, pipeline);
    frame.eyeWidth = setup.width;
    frame.eyeHeight = setup.height;
    // 2. Every configuration at this pose: one untimed run, one timed.
    for (size_t k = 0; k < setup.configs.size(); ++k) {
      defaults.restore();
      applySets(pipeline, sets);
      applySets(pipeline, setup.configs[k].sets);
      pipeline.param("reference.enabled").value = 0;
      const std::uint32_t key = std::uint32_t(1 + i);
      timeFrame(pipeline, frame, results[k], key, nullptr);
      timeFrame(pipeline, frame, results[k], key, &times[k]);
    }
    std::printf("  %s: frame %zu/%zu (t = %.3f s) done\n", setup.label.c_str(), i + 1,
                setup.loopTimes.size(), t);
    std::fflush(stdout);
  }
  return poseMs;
}

#include "io/renderer_calibration_measure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "core/frame.h"
#include "core/pipeline.h"
#include "gl/gpu_scene.h"
#include "gl/nbuffer_build.h"
#include "scene/scene_builtin.h"

namespace {

constexpr int kWidth = 256, kHeight = 192, kFrames = 3;

struct Timed {
  double build = 0, nbuffer = 0, minmax = 0, classify = 0, trace = 0;
};

double medianOf(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

Timed timeConfiguration(Pipeline& pipeline, Frame& frame, int resolution,
                        const char* hierarchy, int rays) {
  for (const std::string& assignment :
       {"light.resolution=" + std::to_string(resolution), std::string("trace.hierarchy=") + hierarchy,
        "trace.rays=" + std::to_string(rays)})
    if (std::string problem = pipeline.set(assignment); !problem.empty())
      throw std::logic_error("calibration: " + problem);
  std::vector<double> build, nbuffer, minmax, classify, trace;
  const auto ms = [&](const char* stage) {
    const StageTime& time = pipeline.lastTime(stage);
    return time.ran ? time.milliseconds : 0.0;
  };
  for (int i = 0; i <= kFrames; ++i) {
    frame.frameKey = std::uint32_t(i);
    pipeline.run(frame, {"trace.visibility"});
    if (i == 0) continue;  // warm-up: programs linked, textures allocated
    build.push_back(ms("light_layers") + ms("nbuffer") + ms("minmax"));
    nbuffer.push_back(ms("nbuffer"));
    minmax.push_back(ms("minmax"));
    classify.push_back(ms("classify"));
    trace.push_back(ms("trace"));
  }
  return {medianOf(build), medianOf(nbuffer), medianOf(minmax), medianOf(classify), medianOf(trace)};
}

double mapBuildWork(int resolution) {  // as app/scene/auto_settings.cpp
  return double(resolution) * double(resolution) * (std::log2(double(resolution)) + 3.0);
}

double twoDigits(double value) {  // the nearest double to the 2-digit decimal (5.1, not 5.1000000000000005)
  char text[32];
  std::snprintf(text, sizeof text, "%.2g", value);
  return std::strtod(text, nullptr);
}

}  // namespace

RendererCalibration measureRendererCalibration() {
  const Scene scene = makeBuiltinScene("spheres");
  Pipeline pipeline;
  GpuScene gpuScene(scene);
  Frame frame(scene, gpuScene, pipeline);
  frame.eyeWidth = kWidth;
  frame.eyeHeight = kHeight;
  const Timed a = timeConfiguration(pipeline, frame, 512, "nbuffer", 2);
  const Timed b = timeConfiguration(pipeline, frame, 1024, "nbuffer", 2);
  const Timed c = timeConfiguration(pipeline, frame, 512, "nbuffer", 4);
  const Timed d = timeConfiguration(pipeline, frame, 512, "minmax", 2);
  const double pixels = double(kWidth) * kHeight;

  RendererCalibration out;
  out.buildMsPerTexelLevel = (b.build - a.build) / (mapBuildWork(1024) - mapBuildWork(512));
  out.traceMsPerPixelRay = (c.trace - a.trace) / (pixels * (16 - 4));
  out.nbufferExtraMsPerTexelLevel =
      (a.nbuffer - d.minmax) / (512.0 * 512.0 * nbufferLevelCount(512, 512));
  out.minmaxExtraMsPerEyePixel = ((d.classify + d.trace) - (a.classify + a.trace)) / pixels;
  std::vector<std::string> notes;
  const auto ratio = [&](double numerator, double denominator, double fallback, const char* name) {
    const double value = numerator / denominator;
    if (numerator > 0 && denominator > 0 && value >= kMinCrossover && value <= kMaxCrossover)
      return twoDigits(value);
    char text[200];
    std::snprintf(text, sizeof text, "%s not resolved (%.3g / %.3g): the constant %g kept", name,
                  numerator, denominator, fallback);
    notes.push_back(text);
    return fallback;
  };
  out.texelLevelsPerPixelRay = ratio(out.traceMsPerPixelRay, out.buildMsPerTexelLevel,
                                     kFallbackTexelLevelsPerPixelRay, "texel-levels per pixel-ray");
  out.nbufferTexelLevelsPerEyePixel =
      ratio(out.minmaxExtraMsPerEyePixel, out.nbufferExtraMsPerTexelLevel,
            kFallbackNBufferTexelLevelsPerEyePixel, "N-buffer crossover");
  for (size_t i = 0; i < notes.size(); ++i) out.notes += (i ? "; " : "") + notes[i];
  return out;
}

int applyRendererCalibration(const std::string& command, const std::string& override) {
  std::string log;
  int status = 0;
  try {
    setActiveRendererCalibration(
        resolveRendererCalibration(calibrationRequest(override), measureRendererCalibration, &log));
  } catch (const std::invalid_argument& error) {
    log += error.what() + std::string("\n");
    status = 2;
  } catch (const std::exception& error) {
    log += "calibration failed: " + std::string(error.what()) + "\n";
    status = 1;
  }
  for (size_t start = 0; start < log.size();) {
    const size_t end = log.find('\n', start);
    std::fprintf(stderr, "penumbra %s: %s\n", command.c_str(), log.substr(start, end - start).c_str());
    start = end == std::string::npos ? log.size() : end + 1;
  }
  return status;
}

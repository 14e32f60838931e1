#include "bench/bench_report.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <thread>

#include "bench/bench_animated.h"
#include "bench/bench_configs.h"
#include "bench/bench_measure.h"
#include "bench/bench_output.h"
#include "base/input_error.h"
#include "core/pipeline.h"
#include "gl/gl_context.h"
#include "io/renderer_calibration_measure.h"
#include "io/output_path.h"
#include "reference/reference_cache.h"
#include "reference/reference_request.h"
#include "scene/scene_builtin.h"
#include "scene/scene_checks.h"

namespace {

std::string firstLine(const std::string& path, const std::string& prefix = "") {
  std::ifstream file(path);
  for (std::string line; std::getline(file, line);)
    if (prefix.empty() || line.rfind(prefix, 0) == 0)
      return prefix.empty() ? line : line.substr(line.find(':') + 2);
  return "unknown";
}

// "0.52 0.61 0.70": the 1, 5 and 15 minute load averages.
std::string loadAverage() {
  const std::string line = firstLine("/proc/loadavg");
  size_t end = 0;
  for (int field = 0; field < 3 && end != std::string::npos; ++field) end = line.find(' ', end + 1);
  return line.substr(0, end);
}

// The tracing time recorded next to a cached reference (0 if unknown).
double cachedReferenceSeconds(const std::string& key) {
  try {
    std::ifstream file(referenceCacheDirectory() / (key + ".json"));
    return nlohmann::json::parse(file).value("seconds", 0.0);
  } catch (const std::exception&) {
    return 0.0;
  }
}

}  // namespace

int runBench(const BenchOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  // 1. The output path and the plan; every assignment checked before any GL work.
  checkOutputDirectory(options.out, "--out", "results.json");  // an earlier bench output or new
  std::vector<std::string> warnings;
  Scene scene;
  std::vector<BenchSetup> setups;
  std::unique_ptr<GlContext> context;  // declared before the pipeline: GL objects die first
  Pipeline pipeline;
  const ParamSnapshot defaults(pipeline);
  try {
    const Scene rest = loadScene(options.scene, warnings);
    if (!std::isfinite(options.time) || std::abs(options.time) > 1e9)
      throw InputError("--time must be finite and within +-1e9 seconds");
    if (std::string problem = posedSceneProblem(rest, options.time); !problem.empty())
      throw InputError(printable(options.scene, 200) + ": " + problem);
    scene = poseAt(rest, options.time);
    BenchPlanOptions planOptions{options.preset, options.sweeps, options.width, options.height,
                                 options.fps, options.loopFrames, options.time};
    // Preset animated poses each frame itself: it plans from the scene at rest.
    setups = makeBenchPlan(options.preset == "animated" ? rest : scene, planOptions, pipeline);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "penumbra bench: %s\n", error.what());
    return 2;
  }
  for (const std::string& warning : lightWarnings(scene)) warnings.push_back(warning);
  for (const std::string& warning : warnings) std::fprintf(stderr, "warning: %s\n", warning.c_str());
  size_t configurationCount = 0;
  for (const BenchSetup& setup : setups)
    for (const BenchConfig& config : setup.configs) {
      ++configurationCount;
      std::string problem = applySets(pipeline, options.sets);
      if (problem.empty()) problem = applySets(pipeline, config.sets);
      defaults.restore();
      if (!problem.empty()) {
        std::fprintf(stderr, "penumbra bench: %s: %s\n", config.label.c_str(), problem.c_str());
        return 2;
      }
    }
  std::string error;
  context = GlContext::createHeadless(error);
  if (!context) {
    std::fprintf(stderr, "penumbra bench: %s\n", error.c_str());
    return 1;
  }
  // `auto` per renderer (gl/renderer_calibration.h).
  if (int status = applyRendererCalibration("bench"); status != 0) return status;

  BenchRunInfo info;
  info.scene = scene.name;
  info.preset = options.preset.empty() ? "default" : options.preset;
  info.commandLine = options.commandLine;
  info.renderer = context->renderer();
  info.cpu = firstLine("/proc/cpuinfo", "model name") + ", " +
             std::to_string(std::max(1u, std::thread::hardware_concurrency())) + " threads" +
             (std::getenv("LP_NUM_THREADS") ? std::string(", LP_NUM_THREADS=") + std::getenv("LP_NUM_THREADS") : "");
  info.loadBefore = loadAverage();
  info.frames = options.frames;
  info.warmup = options.warmup;
  info.rounds = std::max(1, std::min(options.rounds, options.frames));
  info.referenceSamples = options.referenceSamples;
  {
    const std::time_t now = std::time(nullptr);
    char text[64];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    info.started = text;
  }

  try {
    // 2. The references: cached, or estimated from a sample of pixels; refuse if too long.
    std::printf("penumbra bench: %s, preset %s, %zu setup(s), %zu configuration(s), on %s\n",
                scene.name.c_str(), info.preset.c_str(), setups.size(), configurationCount,
                info.renderer.c_str());
    std::fflush(stdout);
    double estimate = 0;
    int uncached = 0;
    std::vector<double> cachedSeconds(setups.size(), 0.0);  // how long a cached one took
    for (const BenchSetup& setup : setups) {
      GpuScene gpuScene(setup.scene);
      Frame frame(setup.scene, gpuScene, pipeline);
      frame.eyeWidth = setup.width;
      frame.eyeHeight = setup.height;
      defaults.restore();
      applySets(pipeline, options.sets);
      pipeline.param("reference.enabled").value = 0;  // only the G-buffer is needed here
      pipeline.run(frame);
      const ReferenceRequest request = makeReferenceRequest(
          frame, frame.texture("gbuffer.wsPosition"), frame.texture("gbuffer.wsNormal"),
          options.referenceSamples, pipeline.param("reference.sampling").asEnum() == "stratified");
      const std::string key = referenceCacheKey(setup.scene, request);
      if (std::filesystem::exists(referenceCacheDirectory() / (key + ".exr"))) {
        cachedSeconds[&setup - setups.data()] = cachedReferenceSeconds(key);
        continue;
      }
      const ReferenceTracer tracer(setup.scene);
      const double seconds = tracer.estimateSeconds(request);
      estimate += seconds;
      ++uncached;
      std::printf("  reference %-40s ~%.1f s (%zu occluder triangles, %dx%d, %dx%d samples)\n",
                  setup.label.c_str(), seconds, tracer.occluderTriangles(), setup.width,
                  setup.height, options.referenceSamples, options.referenceSamples);
      std::fflush(stdout);
    }
    if (estimate > options.timeLimit) {
      std::fprintf(stderr,
                   "penumbra bench: refusing to start: the exact reference of %d setup(s) would "
                   "take about %.0f s on this machine (timed on every 97th receiver pixel), more "
                   "than --time-limit %.0f s. Lower --reference-samples (now %d), the image size, "
                   "or raise --time-limit.\n",
                   uncached, estimate, options.timeLimit, options.referenceSamples);
      return 2;
    }
    std::printf("  references: %d to compute (~%.1f s), %zu cached\n", uncached, estimate,
                setups.size() - size_t(uncached));
    std::fflush(stdout);

    // 3. Every configuration against the reference (one frame, key 0), then timed frames in
    //    rounds: each round visits every configuration of the setup for a share of the
    //    frames, so a change of load on the shared cores spreads over all of them instead of
    //    landing on a few. One untimed frame after each switch (textures reallocate).
    std::vector<BenchResult> results;
    size_t done = 0;
    const int rounds = std::max(1, std::min(options.rounds, options.frames));
    for (size_t s = 0; s < setups.size(); ++s) {
      BenchSetup& setup = setups[s];
      GpuScene gpuScene(setup.scene);
      Frame frame(setup.scene, gpuScene, pipeline);
      frame.eyeWidth = setup.width;
      frame.eyeHeight = setup.height;
      const size_t first = results.size();
      std::vector<FrameTimes> times(setup.configs.size());
      // An animated setup: the error frames here, its timed frames over its loop below.
      for (int round = 0; round < (setup.animated() ? 1 : rounds); ++round) {
        const int share = options.frames / rounds + (round < options.frames % rounds ? 1 : 0);
        for (size_t k = 0; k < setup.configs.size(); ++k) {
          const BenchConfig& config = setup.configs[k];
          defaults.restore();
          applySets(pipeline, options.sets);
          applySets(pipeline, config.sets);
          if (round == 0) {
            results.emplace_back();
            if (!measureError(pipeline, frame, s, config, options.referenceSamples, results.back()))
              throw std::runtime_error("reference still pending for " + config.label);
          }
          if (setup.animated()) continue;
          const BenchResult& r = results[first + k];
          pipeline.param("reference.enabled").value = 0;
          const int warmup = round == 0 ? options.warmup : 1;
          for (int i = 0; i < warmup + share; ++i)
            timeFrame(pipeline, frame, r, std::uint32_t(1 + round * 1000 + i),
                      i < warmup ? nullptr : &times[k]);
        }
        if (!setup.animated())
          std::printf("  %s: round %d/%d done\n", setup.label.c_str(), round + 1, rounds);
        std::fflush(stdout);
      }
      if (setup.animated())
        setup.poseMs = timeLoop(pipeline, defaults, options.sets, setup,
                                std::vector<BenchResult>(results.begin() + long(first), results.end()), times);
      for (size_t k = 0; k < setup.configs.size(); ++k) {
        BenchResult& r = results[first + k];
        summarize(times[k], r);
        if (setup.animated()) {
          r.loopTimes = setup.loopTimes;
          r.loopMs = times[k].totals;
          if (times[k].stages.count("bvh_build")) r.loopBvhMs = times[k].stages.at("bvh_build");
        }
        if (r.referenceCache == 2) r.referenceSeconds = cachedSeconds[s];
        std::printf("[%3zu/%zu] %s | %-40s %8.1f ms  mean|e| in shadow %.4f  RMSE %.4f\n", ++done,
                    configurationCount, setup.label.c_str(), r.label.c_str(), r.msMedian,
                    r.error.meanAbsInShadow, r.error.rmse);
      }
      std::fflush(stdout);
    }

    // 4. The files.
    info.loadAfter = loadAverage();
    info.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    markParetoFrontiers(results);
    const auto written = writeBenchOutputs(options.out, info, setups, results);
    std::printf("penumbra bench: %.0f s; load average before %s, after %s\n", info.seconds,
                info.loadBefore.c_str(), info.loadAfter.c_str());
    for (const auto& path : written) std::printf("wrote %s\n", path.c_str());
  } catch (const std::exception& failure) {
    std::fprintf(stderr, "penumbra bench: %s\n", failure.what());
    return 1;
  }
  return 0;
}

#include "bench/bench_report.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <thread>

#include "bench/bench_configs.h"
#include "bench/bench_output.h"
#include "core/input_error.h"
#include "core/pipeline.h"
#include "gl/gl_context.h"
#include "io/output_path.h"
#include "reference/reference_cache.h"
#include "reference/reference_request.h"
#include "scene/scene_builtin.h"
#include "scene/scene_checks.h"

namespace {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

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

// Every parameter back to its declared default between configurations.
struct Defaults {
  std::vector<std::pair<Param*, double>> values;
  explicit Defaults(const Pipeline& pipeline) {
    for (const std::string& key : pipeline.paramKeys())
      values.push_back({&pipeline.param(key), pipeline.param(key).value});
  }
  void restore() const {
    for (const auto& [param, value] : values) param->value = value;
  }
};

std::string applySets(Pipeline& pipeline, const std::vector<std::string>& sets) {
  for (const std::string& assignment : sets)
    if (std::string problem = pipeline.set(assignment); !problem.empty()) return problem;
  return "";
}

std::string family(const BenchResult& r) {
  if (r.method == "hard_shadow") return "hard shadow";
  const int layers = r.layers == "one" ? 1 : r.layers == "two" ? 2 : 3;
  std::string name = (r.search == "linear_binary" ? "linear/binary" : r.search) + " " +
                     std::to_string(layers) + "L";
  if (!r.deferred) name += " forward";
  if (!r.filter) name += " unfiltered";
  return name;
}

// The configuration's parameters and its error against the reference, on one frame (key
// 0; the reference is computed on the first call of a setup, then comes from memory).
BenchResult measureError(Pipeline& pipeline, Frame& frame, size_t setup, const BenchConfig& config,
                         const BenchOptions& options) {
  BenchResult r;
  r.setup = setup;
  r.label = config.label;
  r.method = config.method;
  r.search = pipeline.param("trace.search").asEnum();
  r.layers = pipeline.param("light.layers").asEnum();
  r.rays = pipeline.param("trace.rays").asInt();
  r.map = pipeline.param("light.resolution").asInt();
  r.deferred = pipeline.param("trace.deferred").asBool();
  r.filter = pipeline.param("filter.enabled").asBool();
  r.family = family(r);
  pipeline.param("reference.enabled").value = 1;
  pipeline.set("reference.samples=" + std::to_string(options.referenceSamples));
  frame.frameKey = 0;
  pipeline.run(frame);
  const auto& c = frame.counters;
  if (!c.count("error.rmse"))
    throw std::runtime_error("no error metrics for " + config.label + " (reference missing)");
  r.error.rmse = c.at("error.rmse");
  r.error.max = c.at("error.max");
  r.error.meanAbsInShadow = c.at("error.meanAbsInShadow");
  r.error.p99 = c.at("error.p99");
  r.error.meanSigned = c.at("error.meanSigned");
  r.error.pixels = size_t(c.at("error.pixels"));
  r.error.pixelsInShadow = size_t(c.at("error.pixelsInShadow"));
  r.referenceSeconds = c.at("reference.seconds");
  r.referenceCache = int(c.at("reference.cacheHit"));
  r.fetchesPerRay = r.method == "hard_shadow" ? 1.0 : c.at("trace.fetchesPerRay");
  r.raysTraced = r.method == "hard_shadow" ? 0.0 : c.at("trace.rays");
  return r;
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

std::vector<std::string> timedStages(const std::string& method, bool filter) {
  if (method == "hard_shadow") return {"gbuffer", "light_layers", "hard_shadow", "composite"};
  std::vector<std::string> stages = {"gbuffer", "light_layers", "nbuffer", "classify", "trace"};
  if (filter) stages.push_back("filter");
  stages.push_back("composite");
  return stages;
}

int runBench(const BenchOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  // 1. The output path and the plan; every assignment checked before any GL work.
  checkOutputDirectory(options.out, "--out", "");
  std::vector<std::string> warnings;
  Scene scene;
  std::vector<BenchSetup> setups;
  try {
    scene = loadScene(options.scene, warnings);
    BenchPlanOptions planOptions{options.preset, options.sweeps, options.width, options.height};
    setups = makeBenchPlan(scene, planOptions);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "penumbra bench: %s\n", error.what());
    return 2;
  }
  for (const std::string& warning : lightWarnings(scene)) warnings.push_back(warning);
  for (const std::string& warning : warnings) std::fprintf(stderr, "warning: %s\n", warning.c_str());
  std::unique_ptr<GlContext> context;  // declared before the pipeline: GL objects die first
  Pipeline pipeline;
  const Defaults defaults(pipeline);
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
      const BenchSetup& setup = setups[s];
      GpuScene gpuScene(setup.scene);
      Frame frame(setup.scene, gpuScene, pipeline);
      frame.eyeWidth = setup.width;
      frame.eyeHeight = setup.height;
      const size_t first = results.size();
      std::vector<std::vector<double>> totals(setup.configs.size()), traces(setup.configs.size());
      for (int round = 0; round < rounds; ++round) {
        const int share = options.frames / rounds + (round < options.frames % rounds ? 1 : 0);
        for (size_t k = 0; k < setup.configs.size(); ++k) {
          const BenchConfig& config = setup.configs[k];
          defaults.restore();
          applySets(pipeline, options.sets);
          applySets(pipeline, config.sets);
          if (round == 0) results.push_back(measureError(pipeline, frame, s, config, options));
          const BenchResult& r = results[first + k];
          const std::vector<std::string> stages = timedStages(r.method, r.filter);
          pipeline.param("reference.enabled").value = 0;
          const int warmup = round == 0 ? options.warmup : 1;
          for (int i = 0; i < warmup + share; ++i) {
            frame.frameKey = std::uint32_t(1 + round * 1000 + i);
            pipeline.run(frame);
            if (i < warmup) continue;
            double total = 0;
            for (const StageTime& time : pipeline.lastTimes()) {
              if (std::find(stages.begin(), stages.end(), time.stage) != stages.end())
                total += time.milliseconds;
              if (time.stage == "trace") traces[k].push_back(time.milliseconds);
            }
            totals[k].push_back(total);
          }
        }
        std::printf("  %s: round %d/%d done\n", setup.label.c_str(), round + 1, rounds);
        std::fflush(stdout);
      }
      for (size_t k = 0; k < setup.configs.size(); ++k) {
        BenchResult& r = results[first + k];
        r.frames = int(totals[k].size());
        r.msMedian = median(totals[k]);
        r.msMin = *std::min_element(totals[k].begin(), totals[k].end());
        r.msMax = *std::max_element(totals[k].begin(), totals[k].end());
        r.traceMsMedian = r.method == "hard_shadow" ? 0.0 : median(traces[k]);
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

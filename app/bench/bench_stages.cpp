#include "bench/bench_stages.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "core/input_error.h"
#include "gl/gl_context.h"
#include "io/image_export.h"
#include "io/output_path.h"
#include "core/pipeline.h"
#include "scene/scene_builtin.h"
#include "scene/scene_checks.h"

namespace {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

struct Config {
  std::string search;
  int rays;
  bool deferred;
};

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, ',');)
    if (!part.empty()) parts.push_back(part);
  return parts;
}

}  // namespace

int runBenchStages(const BenchStagesOptions& options) {
  // 1. Input first: the output path and every scene, before any GL work.
  checkOutputFile(options.out, "--out");
  const std::vector<std::string> sceneNames = split(options.scenes);
  if (sceneNames.empty())
    throw InputError("--scenes '" + printable(options.scenes) + "' names no scene (e.g. cube,engine)");
  std::vector<Scene> scenes;
  for (const std::string& sceneName : sceneNames) {
    std::vector<std::string> warnings;
    scenes.push_back(loadScene(sceneName, warnings));
    for (const std::string& warning : lightWarnings(scenes.back())) warnings.push_back(warning);
    for (const std::string& warning : warnings) std::fprintf(stderr, "warning: %s\n", warning.c_str());
  }
  std::string error;
  auto context = GlContext::createHeadless(error);
  if (!context) {
    std::fprintf(stderr, "penumbra bench-stages: %s\n", error.c_str());
    return 1;
  }
  const std::vector<std::string> stageOrder = {"gbuffer", "hash", "light_layers", "nbuffer",
                                               "classify", "trace", "filter", "composite"};
  std::ostringstream table;
  table << "# Stage benchmark\n\nMachine: " << context->renderer()
        << (std::getenv("LP_NUM_THREADS") ? std::string(", LP_NUM_THREADS=") + std::getenv("LP_NUM_THREADS") : "")
        << ". Eye " << options.width << "x" << options.height << ", shadow map " << options.mapSize
        << "^2, median of " << options.frames << " frames after " << options.warmup
        << " warm-up frames (glFinish + steady clock per stage). Produced by `penumbra bench-stages`.\n\n"
        << "| scene | search | rays | deferred | ";
  for (const std::string& stage : stageOrder) table << stage << " ms | ";
  table << "total ms | fetches/ray | fetches/searched ray | spared by classify |\n|";
  for (size_t i = 0; i < stageOrder.size() + 8; ++i) table << "---|";
  table << "\n";

  for (size_t sceneIndex = 0; sceneIndex < scenes.size(); ++sceneIndex) {
    const std::string& sceneName = sceneNames[sceneIndex];
    const Scene& scene = scenes[sceneIndex];
    GpuScene gpuScene(scene);
    for (const Config& config : std::vector<Config>{{"linear", 2, true}, {"linear_binary", 2, true},
                                                    {"hierarchical", 2, true}, {"hierarchical", 2, false},
                                                    {"linear", 3, true}, {"linear_binary", 3, true},
                                                    {"hierarchical", 3, true}, {"hierarchical", 3, false}}) {
      Pipeline pipeline;
      std::vector<std::string> assignments = options.sets;
      for (const std::string& each :
           {"trace.search=" + config.search, "trace.rays=" + std::to_string(config.rays),
            std::string("trace.deferred=") + (config.deferred ? "true" : "false"),
            "light.resolution=" + std::to_string(options.mapSize)})
        assignments.push_back(each);
      for (const std::string& assignment : assignments)
        if (std::string problem = pipeline.set(assignment); !problem.empty())
          throw InputError("--set " + problem);
      Frame frame(scene, gpuScene, pipeline);
      frame.eyeWidth = options.width;
      frame.eyeHeight = options.height;
      std::map<std::string, std::vector<double>> times;
      std::vector<double> totals;
      for (int i = 0; i < options.warmup + options.frames; ++i) {
        frame.frameKey = std::uint32_t(i);
        pipeline.run(frame);
        if (i < options.warmup) continue;
        double total = 0;
        for (const StageTime& time : pipeline.lastTimes()) {
          times[time.stage].push_back(time.milliseconds);
          total += time.milliseconds;
        }
        totals.push_back(total);
      }
      const auto& c = frame.counters;
      const double receivers = c.at("classify.lit") + c.at("classify.penumbra") + c.at("classify.umbra");
      table << "| " << sceneName << " | " << config.search << " | " << config.rays << "x"
            << config.rays << " | " << (config.deferred ? "yes" : "no") << " | ";
      char cell[64];
      for (const std::string& stage : stageOrder) {
        std::snprintf(cell, sizeof cell, "%.1f", median(times[stage]));
        table << cell << " | ";
      }
      std::snprintf(cell, sizeof cell, "%.1f | %.2f | %.2f | ", median(totals),
                    c.at("trace.rays") ? c.at("trace.fetches") / c.at("trace.rays") : 0.0,
                    c.at("trace.raysSearched") ? c.at("trace.fetches") / c.at("trace.raysSearched") : 0.0);
      table << cell;
      std::snprintf(cell, sizeof cell, "%.1f%% |\n",
                    config.deferred && receivers > 0 ? 100.0 * c.at("trace.pixelsClassified") / receivers : 0.0);
      table << cell;
      std::printf("%s %s %dx%d %s: %.1f ms per frame\n", sceneName.c_str(), config.search.c_str(),
                  config.rays, config.rays, config.deferred ? "deferred" : "forward", median(totals));
      std::fflush(stdout);
    }
  }
  table << "\nfetches/ray counts every ray set up (early outs included); fetches/searched ray "
           "only rays that reached a search loop. Forward rows trace every rasterized "
           "fragment, so classification spares nothing there.\n";
  const std::filesystem::path out(options.out);
  if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
  writeTextFile(out, table.str());
  std::printf("%s\nwritten to %s\n", table.str().c_str(), options.out.c_str());
  return 0;
}

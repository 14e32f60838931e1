#include "bench/bench_stages.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "bench/bench_measure.h"
#include "base/input_error.h"
#include "gl/gl_context.h"
#include "io/renderer_calibration_measure.h"
#include "io/image_export.h"
#include "io/output_path.h"
#include "core/pipeline.h"
#include "scene/scene_builtin.h"
#include "scene/scene_checks.h"

namespace {

// One row: a method and its assignments. The Monte Carlo method (stage `filter`, which
// depends on classify and trace) is swept over search type, rays and deferred; every other
// method of the graph runs with its defaults.
struct Config {
  std::string label, method;
  std::vector<std::string> sets;
};

std::vector<Config> configsOf(const Pipeline& pipeline) {
  std::vector<Config> configs;
  const std::vector<std::string> methods = pipeline.methods();
  const bool monteCarlo = std::find(methods.begin(), methods.end(), "filter") != methods.end() &&
                          pipeline.hasStage("trace");
  if (monteCarlo)
    for (int rays : {2, 3})
      for (const auto& [search, deferred] : std::vector<std::pair<std::string, bool>>{
               {"linear", true}, {"linear_binary", true}, {"hierarchical", true}, {"hierarchical", false}})
        configs.push_back({search + " " + std::to_string(rays) + "x" + std::to_string(rays) +
                               (deferred ? "" : " forward"),
                           "filter",
                           {"trace.search=" + search, "trace.rays=" + std::to_string(rays),
                            std::string("trace.deferred=") + (deferred ? "true" : "false")}});
  for (const std::string& method : methods)
    if (!(monteCarlo && (method == "filter" || method == "trace")))
      configs.push_back({method + " (defaults)", method, {}});
  return configs;
}

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, ',');)
    if (!part.empty()) parts.push_back(part);
  return parts;
}

std::string cell(double value, const char* format = "%.1f") {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
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
  // `auto` per renderer (gl/renderer_calibration.h).
  if (int status = applyRendererCalibration("bench-stages"); status != 0) return status;
  // 2. Every row measured first (the columns are the stages any row's method needs).
  struct Row {
    std::string scene, label;
    std::map<std::string, double> stageMs;
    double total = 0;
    std::map<std::string, double> counters;
    bool traced = false, classified = false;  // the trace runs; it skips classified pixels
  };
  std::vector<Row> rows;
  std::vector<std::string> columns;
  // Memory per stage output (docs/decisions/021-stage-timings.md): every output any row of the
  // first scene wrote, MiB from its format and size, in execution order.
  std::map<std::string, std::pair<std::string, double>> memory;  // output -> (shape, MiB)
  for (size_t sceneIndex = 0; sceneIndex < scenes.size(); ++sceneIndex) {
    const std::string& sceneName = sceneNames[sceneIndex];
    const Scene& scene = scenes[sceneIndex];
    GpuScene gpuScene(scene);
    const std::vector<Config> configs = configsOf(Pipeline{});
    for (const Config& config : configs) {
      Pipeline pipeline;
      std::vector<std::string> assignments = options.sets;
      for (const std::string& each : config.sets) assignments.push_back(each);
      assignments.push_back("light.resolution=" + std::to_string(options.mapSize));
      if (std::string problem = applySets(pipeline, assignments); !problem.empty())
        throw InputError("--set " + problem);
      Frame frame(scene, gpuScene, pipeline);
      frame.eyeWidth = options.width;
      frame.eyeHeight = options.height;
      BenchResult timed;
      timed.method = config.method;
      timed.label = config.label;
      pipeline.run(frame, {pipeline.methodOutput(config.method)});  // decides `auto` choices
      timed.stages = timedStages(pipeline, config.method);
      FrameTimes times;
      for (int i = 0; i < options.warmup + options.frames; ++i)
        timeFrame(pipeline, frame, timed, std::uint32_t(i), i < options.warmup ? nullptr : &times);
      summarize(times, timed);
      for (const auto& stage : pipeline.stages())
        for (const Output& output : stage->outputs()) {
          const std::string key = stage->name() + "." + output.name;
          if (sceneIndex != 0 || !frame.has(key)) continue;
          const GlTexture& texture = frame.texture(key);
          memory[key] = {texture.extentText(), frame.megabytes(key)};
        }
      for (const std::string& stage : pipeline.dependencies({pipeline.methodOutput(config.method)}))
        if (std::find(columns.begin(), columns.end(), stage) == columns.end()) columns.push_back(stage);
      const bool traced = std::find(timed.stages.begin(), timed.stages.end(), "trace") != timed.stages.end();
      const bool classified = traced && pipeline.param("trace.deferred").asBool() &&
                              pipeline.param("trace.use_classification").asBool();
      rows.push_back({sceneName, config.label, timed.stageMs, timed.msMedian, frame.counters,
                      traced, classified});
      std::printf("%s %s: %.1f ms per frame\n", sceneName.c_str(), config.label.c_str(), timed.msMedian);
      std::fflush(stdout);
    }
  }
  // Columns in execution order.
  {
    std::vector<std::string> ordered;
    const Pipeline graph;
    for (const auto& stage : graph.stages())
      if (std::find(columns.begin(), columns.end(), stage->name()) != columns.end())
        ordered.push_back(stage->name());
    columns = ordered;
  }

  // 3. The table.
  std::ostringstream table;
  table << "# Stage benchmark\n\nMachine: " << context->renderer()
        << (std::getenv("LP_NUM_THREADS") ? std::string(", LP_NUM_THREADS=") + std::getenv("LP_NUM_THREADS") : "")
        << ". Eye " << options.width << "x" << options.height << ", shadow map " << options.mapSize
        << "^2, median of " << options.frames << " frames after " << options.warmup
        << " warm-up frames (per stage: " << Pipeline().timingMethod() << "). Each row runs only the stages "
           "its method's visibility depends on (the stage graph); \"-\": not needed by that "
           "method. Produced by `penumbra bench-stages`.\n\n"
        << "| scene | configuration | ";
  for (const std::string& stage : columns) table << stage << " ms | ";
  table << "total ms | fetches/ray | fetches/searched ray | spared by classify |\n|";
  for (size_t i = 0; i < columns.size() + 6; ++i) table << "---|";
  table << "\n";
  for (const Row& row : rows) {
    table << "| " << row.scene << " | " << row.label << " | ";
    for (const std::string& stage : columns)
      table << (row.stageMs.count(stage) ? cell(row.stageMs.at(stage)) : "-") << " | ";
    table << cell(row.total) << " | ";
    // Statistics of the Monte Carlo trace and classification, where the method has them.
    auto counter = [&](const std::string& name) {
      const auto it = row.counters.find(name);
      return it == row.counters.end() ? 0.0 : it->second;
    };
    const double rays = counter("trace.rays"), searched = counter("trace.raysSearched");
    // Spared: receiver pixels classified lit or umbra, which a deferred trace that uses the
    // classification skips (§3.6); a forward trace runs on every fragment.
    const double receivers = counter("classify.lit") + counter("classify.penumbra") + counter("classify.umbra");
    table << (rays > 0 ? cell(counter("trace.fetches") / rays, "%.2f") : "-") << " | "
          << (searched > 0 ? cell(counter("trace.fetches") / searched, "%.2f") : "-") << " | "
          << (row.classified && receivers > 0
                  ? cell(100.0 * (counter("classify.lit") + counter("classify.umbra")) / receivers, "%.1f%%")
                  : row.traced ? "0.0%" : "-")
          << " |\n";
  }
  table << "\nfetches/ray counts every ray set up (early outs included); fetches/searched ray "
           "only rays that reached a search loop. Forward rows trace every rasterized "
           "fragment, so classification spares nothing there.\n";
  table << "\n## Memory per stage output (" << sceneNames.front() << ", eye " << options.width
        << "x" << options.height << ", map " << options.mapSize
        << "^2; MiB from the formats and sizes)\n\n| output | size | MiB |\n|---|---|---|\n";
  const Pipeline graph;  // execution order
  for (const auto& stage : graph.stages())
    for (const Output& output : stage->outputs()) {
      const auto it = memory.find(stage->name() + "." + output.name);
      if (it != memory.end())
        table << "| " << it->first << " | " << it->second.first << " | "
              << cell(it->second.second, "%.2f") << " |\n";
    }
  const std::filesystem::path out(options.out);
  if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
  writeTextFile(out, table.str());
  std::printf("%s\nwritten to %s\n", table.str().c_str(), options.out.c_str());
  return 0;
}

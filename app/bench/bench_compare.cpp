#include "bench/bench_compare.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "bench/bench_measure.h"
#include "io/headless_session.h"
#include "core/pipeline.h"
#include "io/image_export.h"

namespace {

// One configuration: its pipeline, frame and per-frame measurements.
struct Side {
  std::string label;
  std::vector<std::string> sets;
  std::unique_ptr<Pipeline> pipeline;
  std::unique_ptr<Frame> frame;
  std::map<std::string, std::vector<double>> stageMs;  // stages that ran
  std::vector<double> total;
  std::map<std::string, double> counters;  // last frame's
  double error = -1;                       // RMSE against the reference, -1: not measured
  double errorInShadow = -1;
};

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

}  // namespace

int runBenchCompare(const BenchCompareOptions& options) {
  if (options.sides.empty()) {
    std::fprintf(stderr, "penumbra bench-compare: give at least one --side label:key=value;...\n");
    return 2;
  }
  HeadlessSession session;  // the scene checked first, its warnings printed; one GL context
  if (const int status = session.open("bench-compare", options.scene, {}, options.width, options.height);
      status != 0)
    return status;
  const Scene& scene = session.scene;
  GpuScene& gpuScene = *session.gpuScene;
  // 1. One pipeline per side: the common sets, then the side's own.
  std::vector<Side> sides(options.sides.size());
  for (size_t s = 0; s < sides.size(); ++s) {
    const std::string& spec = options.sides[s];
    const size_t colon = spec.find(':');
    sides[s].label = colon == std::string::npos ? spec : spec.substr(0, colon);
    sides[s].sets = options.sets;
    std::string rest = colon == std::string::npos ? "" : spec.substr(colon + 1);
    for (size_t start = 0; start < rest.size();) {
      const size_t end = std::min(rest.find(';', start), rest.size());
      if (end > start) sides[s].sets.push_back(rest.substr(start, end - start));
      start = end + 1;
    }
    sides[s].pipeline = std::make_unique<Pipeline>();
    for (const std::string& assignment : sides[s].sets)
      if (std::string problem = sides[s].pipeline->set(assignment); !problem.empty()) {
        std::fprintf(stderr, "penumbra bench-compare: side '%s': %s\n", sides[s].label.c_str(),
                     problem.c_str());
        return 2;
      }
    sides[s].frame = std::make_unique<Frame>(scene, gpuScene, *sides[s].pipeline);
    sides[s].frame->eyeWidth = options.width, sides[s].frame->eyeHeight = options.height;
  }
  // 2. Frames alternate between the sides.
  for (int i = 0; i < options.warmup + options.frames; ++i)
    for (Side& side : sides) {
      side.frame->frameKey = std::uint32_t(i);
      side.pipeline->run(*side.frame, options.requested);
      if (i < options.warmup) continue;
      double total = 0;
      for (const StageTime& time : side.pipeline->lastTimes()) {
        if (!time.ran) continue;
        side.stageMs[time.stage].push_back(time.milliseconds);
        total += time.milliseconds;
      }
      side.total.push_back(total);
      side.counters = side.frame->counters;
    }
  // 3. Error against the reference, once per side, untimed.
  if (!options.errorOf.empty())
    for (Side& side : sides) {
      for (const std::string& assignment :
           {std::string("reference.enabled=true"), std::string("reference.cache=true"),
            "error.method=" + options.errorOf})
        if (std::string problem = side.pipeline->set(assignment); !problem.empty()) {
          std::fprintf(stderr, "penumbra bench-compare: %s\n", problem.c_str());
          return 2;
        }
      side.pipeline->run(*side.frame, {"error.absolute"});
      side.error = side.frame->counters.at("error.rmse");
      side.errorInShadow = side.frame->counters.at("error.meanAbsInShadow");
    }
  // 4. The table: one row per side; ratios against the first side.
  // Columns: every stage that ran on any side (a side may run a stage the first does not:
  // trace.hierarchy=minmax builds the min-max mipmap instead of the N-buffer).
  std::set<std::string> ranOnAnySide;
  for (const Side& side : sides)
    for (const auto& [stage, values] : side.stageMs) ranOnAnySide.insert(stage);
  const std::vector<std::string> stages(ranOnAnySide.begin(), ranOnAnySide.end());
  std::ostringstream table;
  table << "## " << (options.title.empty() ? "bench-compare" : options.title) << "\n\n"
        << "Machine: " << session.context->renderer() << ". Scene " << options.scene << ", eye "
        << options.width << "x" << options.height << ", median of " << options.frames
        << " frames after " << options.warmup << " warm-up, sides alternating frame by frame ("
        << Pipeline().timingMethod() << "). Common sets:";
  for (const std::string& set : options.sets) table << " `" << set << "`";
  table << ". Produced by `penumbra bench-compare`.\n\n| side | sets | run ms |";
  for (const std::string& stage : stages) table << " " << stage << " ms |";
  for (const std::string& counter : options.counters) table << " " << counter << " |";
  table << " fetches / searched ray |";
  if (!options.errorOf.empty()) table << " " << options.errorOf << " RMSE | mean abs in shadow |";
  table << " run ratio |";
  for (const std::string& stage : stages) table << " " << stage << " ratio |";
  table << "\n|";
  const size_t columns = 5 + 2 * stages.size() + options.counters.size() +
                         (options.errorOf.empty() ? 0 : 2);
  for (size_t c = 0; c < columns; ++c) table << "---|";
  table << "\n";
  for (const Side& side : sides) {
    std::string own;
    for (size_t k = options.sets.size(); k < side.sets.size(); ++k)
      own += (own.empty() ? "" : " ") + side.sets[k];
    table << "| " << side.label << " | " << own << " | " << format("%.1f", median(side.total))
          << " |";
    auto stageMedian = [](const Side& of, const std::string& stage) {
      const auto found = of.stageMs.find(stage);
      return found == of.stageMs.end() ? 0.0 : median(found->second);
    };
    for (const std::string& stage : stages) table << " " << format("%.2f", stageMedian(side, stage)) << " |";
    for (const std::string& counter : options.counters) {
      const auto found = side.counters.find(counter);
      table << " " << (found == side.counters.end() ? "-" : format("%.7g", found->second)) << " |";
    }
    const auto rays = side.counters.find("trace.raysSearched");
    const bool searched = rays != side.counters.end() && rays->second > 0;
    table << " " << (searched ? format("%.2f", side.counters.at("trace.fetches") / rays->second) : "-")
          << " |";
    if (!options.errorOf.empty())
      table << " " << format("%.5f", side.error) << " | " << format("%.5f", side.errorInShadow) << " |";
    table << " " << format("%.3f", median(side.total) / median(sides[0].total)) << " |";
    for (const std::string& stage : stages) {
      const double base = stageMedian(sides[0], stage);
      table << " " << (base > 0 ? format("%.3f", stageMedian(side, stage) / base) : "-") << " |";
    }
    table << "\n";
  }
  table << "\nRatios: each side over the first. Load when run: see the file's header.\n";
  const std::filesystem::path out(options.out);
  if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
  writeTextFile(out, table.str());
  std::printf("%s\nwritten to %s\n", table.str().c_str(), options.out.c_str());
  return 0;
}

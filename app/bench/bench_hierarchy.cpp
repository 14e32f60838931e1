#include "bench/bench_hierarchy.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "bench/bench_measure.h"
#include "io/headless_session.h"
#include "core/pipeline.h"
#include "io/image_export.h"

namespace {

// One hierarchy's pipeline, frame and measurements.
struct Side {
  std::string hierarchy;  // "nbuffer" or "minmax": the trace's choice and the stage timed
  std::unique_ptr<Pipeline> pipeline;
  std::unique_ptr<Frame> frame;
  std::vector<double> build, trace, total;
};

}  // namespace

int runBenchHierarchy(const BenchHierarchyOptions& options) {
  HeadlessSession session;  // the scene checked first, its warnings printed; one GL context
  if (const int status = session.open("bench-hierarchy", options.scene, {}, options.width, options.height);
      status != 0)
    return status;
  const Scene& scene = session.scene;
  GpuScene& gpuScene = *session.gpuScene;
  std::ostringstream table;
  table << "# N-buffer vs min-max mipmap\n\nMachine: " << session.context->renderer() << ". Scene "
        << options.scene << ", eye " << options.width << "x" << options.height
        << ", trace: hierarchical search, median of " << options.frames << " frames after "
        << options.warmup << " warm-up frames, the two hierarchies alternating frame by frame "
        << "(per stage: " << Pipeline().timingMethod()
        << "). Requested output: trace.visibility (classify reads the same hierarchy as "
        << "the trace: each side builds only its own). "
        << "Produced by `penumbra bench-hierarchy`.\n\n"
        << "| map | hierarchy | build ms | MiB | fetches/searched ray | trace ms | frame ms | "
        << "build ratio | memory ratio | fetch ratio | trace ratio | pixels differing |\n"
        << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (int map : options.maps) {
    Side sides[2];
    sides[0].hierarchy = "nbuffer", sides[1].hierarchy = "minmax";
    for (Side& side : sides) {
      side.pipeline = std::make_unique<Pipeline>();
      std::vector<std::string> assignments = options.sets;
      assignments.push_back("trace.search=hierarchical");
      assignments.push_back("trace.hierarchy=" + side.hierarchy);
      assignments.push_back("light.resolution=" + std::to_string(map));
      for (const std::string& assignment : assignments)
        if (std::string problem = side.pipeline->set(assignment); !problem.empty()) {
          std::fprintf(stderr, "penumbra bench-hierarchy: %s\n", problem.c_str());
          return 2;
        }
      side.frame = std::make_unique<Frame>(scene, gpuScene, *side.pipeline);
      side.frame->eyeWidth = options.width, side.frame->eyeHeight = options.height;
    }
    for (int i = 0; i < options.warmup + options.frames; ++i)
      for (Side& side : sides) {
        side.frame->frameKey = std::uint32_t(i);
        side.pipeline->run(*side.frame, {"trace.visibility"});
        if (i < options.warmup) continue;
        double total = 0;
        for (const StageTime& time : side.pipeline->lastTimes()) total += time.milliseconds;
        side.build.push_back(side.pipeline->lastTime(side.hierarchy).milliseconds);
        side.trace.push_back(side.pipeline->lastTime("trace").milliseconds);
        side.total.push_back(total);
      }
    // Both searches are exact: the same rays give the same visibility up to rounding at
    // texel edges; count the pixels that differ.
    const auto a = sides[0].frame->texture("trace.visibility").readFloats();
    const auto b = sides[1].frame->texture("trace.visibility").readFloats();
    size_t differing = 0;
    for (size_t i = 0; i < a.size(); ++i) differing += a[i] != b[i];
    double fetches[2], mib[2];
    for (int s = 0; s < 2; ++s) {
      const auto& c = sides[s].frame->counters;
      fetches[s] = c.at("trace.raysSearched") ? c.at("trace.fetches") / c.at("trace.raysSearched") : 0;
      mib[s] = sides[s].frame->megabytes(sides[s].hierarchy + ".levels");
    }
    for (int s = 0; s < 2; ++s) {
      const Side& side = sides[s];
      char row[512];
      std::snprintf(row, sizeof row, "| %d | %s | %.1f | %.1f | %.2f | %.1f | %.1f | ", map,
                    side.hierarchy.c_str(), median(side.build), mib[s], fetches[s],
                    median(side.trace), median(side.total));
      table << row;
      if (s == 0) {
        table << "1 | 1 | 1 | 1 | |\n";
      } else {
        std::snprintf(row, sizeof row, "%.3f | %.3f | %.2f | %.2f | %zu of %zu |\n",
                      median(side.build) / median(sides[0].build), mib[1] / mib[0],
                      fetches[1] / fetches[0], median(side.trace) / median(sides[0].trace),
                      differing, a.size());
        table << row;
      }
    }
    std::printf("map %d done\n", map);
    std::fflush(stdout);
  }
  table << "\nRatios: min-max / N-buffer (targets at 2048^2: build <= 1/8, memory <= 1/8, "
           "fetches within 1.5x; docs/decisions/024-minmax-mipmap-levels.md). frame ms: the "
           "stages trace.visibility needs (classify reads the side's hierarchy, Eq 3.3; the "
           "min-max side builds no N-buffer).\n";
  const std::filesystem::path out(options.out);
  if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
  writeTextFile(out, table.str());
  std::printf("%s\nwritten to %s\n", table.str().c_str(), options.out.c_str());
  return 0;
}

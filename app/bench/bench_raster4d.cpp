#include "bench/bench_raster4d.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include "core/pipeline.h"
#include "gl/gl_context.h"
#include "reference/reference_request.h"
#include "reference/reference_trace.h"
#include "scene/scene_builtin.h"

namespace {

struct Measured {
  double ms = 0;  // median of the raster4d stage's milliseconds
  std::map<std::string, double> counters;  // of the last run
  std::vector<float> visibility;
  std::unique_ptr<Frame> frame;            // for the reference's request
};

class Bench {
public:
  Bench(const Scene& scene, int width, int height, int frames)
      : scene_(scene), gpuScene_(scene), width_(width), height_(height), frames_(frames) {}

  // raster4d with `sets` (and the scene's light scaled by `lightScale`).
  Measured raster4d(const std::vector<std::string>& sets, float lightScale = 1, int frames = -1) {
    Scene scene = scene_;
    scene.light.width *= lightScale;
    scene.light.height *= lightScale;
    scenes_.push_back(std::make_unique<Scene>(scene));
    pipelines_.push_back(std::make_unique<Pipeline>());
    Pipeline& pipeline = *pipelines_.back();
    pipeline.set("raster4d.enabled=true");  // off by default
    for (const std::string& assignment : sets)
      if (const std::string problem = pipeline.set(assignment); !problem.empty())
        throw std::invalid_argument(problem);
    Measured result;
    result.frame = std::make_unique<Frame>(*scenes_.back(), gpuScene_, pipeline);
    result.frame->eyeWidth = width_;
    result.frame->eyeHeight = height_;
    std::vector<double> times;
    for (int i = 0; i < 1 + (frames < 0 ? frames_ : frames); ++i) {
      pipeline.run(*result.frame);
      for (const StageTime& time : pipeline.lastTimes())
        if (time.stage == "raster4d" && i > 0) times.push_back(time.milliseconds);
    }
    std::sort(times.begin(), times.end());
    result.ms = times[times.size() / 2];
    for (const auto& [key, value] : result.frame->counters)
      if (key.rfind("raster4d.", 0) == 0) result.counters[key.substr(9)] = value;
    result.visibility = result.frame->texture("raster4d.visibility").readFloats();
    return result;
  }

  // The Embree reference at raster4d's samples for the same frame: milliseconds (one run,
  // every core) and the largest visibility difference.
  std::pair<double, double> embree(const Measured& measured, int m) {
    if (!tracer_) tracer_ = std::make_unique<ReferenceTracer>(scene_);
    const ReferenceRequest request = makeReferenceRequest(
        *measured.frame, measured.frame->texture("gbuffer.wsPosition"),
        measured.frame->texture("gbuffer.wsNormal"), m, false);
    std::vector<float> visibility;
    const auto start = std::chrono::steady_clock::now();
    tracer_->trace(request, visibility);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    double worst = 0;
    for (size_t i = 0; i < visibility.size(); ++i)
      worst = std::max(worst, double(std::fabs(visibility[i] - measured.visibility[i])));
    return {ms, worst};
  }

private:
  const Scene& scene_;
  GpuScene gpuScene_;
  int width_, height_, frames_;
  std::unique_ptr<ReferenceTracer> tracer_;
  std::vector<std::unique_ptr<Scene>> scenes_;
  std::vector<std::unique_ptr<Pipeline>> pipelines_;
};

std::string samples(int m) { return "raster4d.samples=" + std::to_string(m); }

std::string fixed(double value, int digits = 1) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

}  // namespace

int runBenchRaster4d(const BenchRaster4dOptions& options) {
  std::string error;
  auto context = GlContext::createHeadless(error);
  if (!context) {
    std::fprintf(stderr, "penumbra bench-raster4d: %s\n", error.c_str());
    return 1;
  }
  std::ostringstream speed, steps, lightSize, optimizations;
  speed << "| scene | m x m | raster4d ms | Embree ms | Embree / raster4d | max abs visibility "
           "difference |\n|---|---|---|---|---|---|\n";
  steps << "| scene | m x m | STEP 2 | STEP 3 | STEP 4 | STEP 5 | resolve | bands | STEP 5 "
           "dispatches |\n|---|---|---|---|---|---|---|---|---|\n";
  lightSize << "| scene | light side x | raster4d ms | pairs kept |\n|---|---|---|---|\n";
  optimizations << "| scene | receivers | sample redundancy (proj4 stored / receivers) | "
                   "early rejection speed-up | row-mask speed-up | row-culling speed-up (ours) | "
                   "relevant pairs before rejection | after |\n|---|---|---|---|---|---|---|---|\n";
  std::stringstream sceneList(options.scenes);
  for (std::string name; std::getline(sceneList, name, ',');) {
    std::vector<std::string> warnings;
    Scene scene;
    try {
      scene = loadScene(name, warnings);
    } catch (const std::exception& failure) {
      std::fprintf(stderr, "penumbra bench-raster4d: %s\n", failure.what());
      return 2;
    }
    Bench bench(scene, options.width, options.height, options.frames);
    std::fprintf(stderr, "bench-raster4d: %s\n", name.c_str());
    for (int m : {8, 16, 32, 64}) {  // Tables 1, 3, 4
      std::fprintf(stderr, "  %dx%d samples\n", m, m);
      const Measured r = bench.raster4d({samples(m)});
      const auto [embreeMs, worst] = bench.embree(r, m);
      speed << "| " << name << " | " << m << "x" << m << " | " << fixed(r.ms) << " | "
            << fixed(embreeMs) << " | " << fixed(embreeMs / r.ms) << " | " << fixed(worst, 5) << " |\n";
      const auto& c = r.counters;
      steps << "| " << name << " | " << m << "x" << m << " | " << fixed(c.at("step2Ms")) << " | "
            << fixed(c.at("step3Ms")) << " | " << fixed(c.at("step4Ms")) << " | "
            << fixed(c.at("step5Ms")) << " | " << fixed(c.at("resolveMs")) << " | "
            << c.at("bands") << " | " << c.at("step5Chunks") << " |\n";
    }
    for (float scale : {0.5f, 1.0f, 2.0f, 3.0f}) {  // Table 5
      const Measured r = bench.raster4d({samples(32)}, scale);
      lightSize << "| " << name << " | " << fixed(scale) << " | " << fixed(r.ms) << " | "
                << r.counters.at("pairsKept") << " |\n";
    }
    // Tables 2 and 7 at 32 x 32 (the slow variants timed once, on the chosen scenes).
    const Measured base = bench.raster4d({samples(32)});
    const auto& c = base.counters;
    const std::string relevant =
        fixed(100 * c.at("pairsOccluding") / std::max(1.0, c.at("pairsConsidered"))) + "% | " +
        fixed(100 * c.at("pairsOccluding") / std::max(1.0, c.at("pairsKept"))) + "% |\n";
    if (!options.toggleScenes.empty() &&
        ("," + options.toggleScenes + ",").find("," + name + ",") == std::string::npos) {
      optimizations << "| " << name << " | " << c.at("receivers") << " | - | - | - | - | " << relevant;
      continue;
    }
    std::fprintf(stderr, "  optimizations off\n");
    const Measured proj4 = bench.raster4d({samples(32), "raster4d.sample_assignment=proj4"}, 1, 1);
    const Measured noRejection = bench.raster4d({samples(32), "raster4d.early_rejection=false"}, 1, 1);
    const Measured noRows = bench.raster4d({samples(32), "raster4d.row_masks=false"}, 1, 1);
    const Measured noCulling = bench.raster4d({samples(32), "raster4d.row_culling=false"}, 1, 1);
    optimizations << "| " << name << " | " << c.at("receivers") << " | "
                  << fixed(proj4.counters.at("samplesStored") / c.at("receivers")) << " | "
                  << fixed(noRejection.ms / base.ms) << "x | " << fixed(noRows.ms / base.ms) << "x | "
                  << fixed(noCulling.ms / base.ms) << "x | " << relevant;
  }
  std::ofstream file(options.out);
  if (!file) {
    std::fprintf(stderr, "penumbra bench-raster4d: cannot write %s\n", options.out.c_str());
    return 2;
  }
  file << "# raster4d (4D rasterization, Wang et al. 2020) against the Embree reference\n\n"
       << "Machine: " << context->renderer() << ", " << std::thread::hardware_concurrency()
       << " CPU threads (Embree uses all of them). Eye " << options.width << "x" << options.height
       << ", FB 128x128, median of " << options.frames << " runs after one warm-up (glFinish + "
       << "steady clock); Embree: one run of the same frame with the same light samples "
       << "(reference.sampling=uniform). Produced by `penumbra bench-raster4d --scenes "
       << options.scenes << "`.\n\n## Speed against ray tracing (Tables 1 and 4)\n\n"
       << speed.str() << "\n## Milliseconds per step (Table 3)\n\n" << steps.str()
       << "\n## Light size (Table 5), 32x32 samples\n\n" << lightSize.str()
       << "\n## Optimizations (Table 2) and pairing efficiency (Table 7), 32x32 samples\n\n"
       << optimizations.str();
  std::fprintf(stderr, "wrote %s\n", options.out.c_str());
  return 0;
}

#include "bench/bench_reference.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "core/frame.h"
#include "core/pipeline.h"
#include "reference/error_metrics.h"
#include "reference/reference_request.h"
#include "reference/reference_trace.h"

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The graph's stages the reference's rays depend on: the producers of its inputs (the
// G-buffer, the light frame), without the stage `reference` itself.
std::vector<std::string> inputStages(const Pipeline& pipeline) {
  std::vector<std::string> stages = pipeline.dependencies({"reference.visibility"});
  stages.erase(std::remove(stages.begin(), stages.end(), "reference"), stages.end());
  return stages;
}

int samplesOf(const BenchResult& r) { return std::stoi(r.params.at("reference.samples")); }

ReferenceRequest requestOf(const Frame& frame, int samples) {
  return makeReferenceRequest(frame, frame.texture("gbuffer.wsPosition"),
                              frame.texture("gbuffer.wsNormal"), samples, /*stratified=*/false);
}

}  // namespace

bool measureReferenceError(Pipeline& pipeline, Frame& frame, size_t setup,
                           const BenchConfig& config, int truthSamples, BenchResult& r) {
  // 1. What is measured.
  r = BenchResult{};
  r.setup = setup;
  r.label = config.label;
  r.method = "reference";
  r.family = config.family.empty() ? "reference" : config.family;
  r.sets = config.sets;
  const int m = config.referenceSamples;
  r.params["reference.samples"] = std::to_string(m);
  r.params["reference.sampling"] = "uniform";
  r.stages = inputStages(pipeline);
  r.stages.push_back("readback");
  if (config.rebuildBvh) r.stages.push_back("bvh_build");
  r.stages.push_back("embree_trace");

  // 2. The truth and the pixels that count, as the error stage has them (frame key 0).
  pipeline.param("reference.enabled").value = 1;
  pipeline.set("reference.samples=" + std::to_string(truthSamples));
  frame.frameKey = 0;
  const std::string mask = pipeline.source("error", "mask"), flag = pipeline.source("error", "flag");
  const bool receiversOnly = pipeline.param("error.pixels").asEnum() == "receivers";
  std::vector<std::string> requested = {"reference.visibility", mask};
  if (receiversOnly) requested.push_back(flag);
  pipeline.run(frame, requested);
  pipeline.param("reference.enabled").value = 0;
  const auto& c = frame.counters;
  if (c.count("reference.pending")) return false;
  if (!frame.has("reference.visibility"))
    throw std::runtime_error("no truth for " + config.label + " (reference missing)");
  const std::vector<float> truth = frame.texture("reference.visibility").readFloats();
  const std::vector<float> classes = frame.texture(mask).readFloats();
  std::vector<float> receiver;
  if (receiversOnly) receiver = frame.texture(flag).readFloats();
  r.referenceSeconds = c.count("reference.seconds") ? c.at("reference.seconds") : 0.0;
  r.referenceCache = c.count("reference.cacheHit") ? int(c.at("reference.cacheHit")) : 0;

  // 3. Its own image at m x m, from a BVH of this pose.
  const ReferenceRequest request = requestOf(frame, m);
  const ReferenceTracer tracer(frame.scene);
  std::vector<float> visibility;
  if (!tracer.trace(request, visibility)) throw std::runtime_error(config.label + ": cancelled");
  r.error = computeErrorMetrics(visibility, truth,
                                countedPixels(classes, receiversOnly ? &receiver : nullptr),
                                frame.eyeWidth, frame.eyeHeight);
  r.counters["reference.occluderTriangles"] = double(tracer.occluderTriangles());
  r.counters["reference.raysCast"] = double(tracer.raysCast());
  r.counters["reference.samples"] = double(m) * m;
  return true;
}

ReferenceFrameWork prepareReferenceFrame(Pipeline& pipeline, Frame& frame, const BenchResult& r,
                                         std::uint32_t frameKey) {
  ReferenceFrameWork work;
  // 1. The G-buffer and the light frame of this pose, timed by the pipeline.
  frame.frameKey = frameKey;
  pipeline.param("reference.enabled").value = 0;  // the stage itself does nothing
  pipeline.run(frame, {"reference.visibility"});
  for (const StageTime& time : pipeline.lastTimes())
    if (time.ran) work.ms[time.stage] = time.milliseconds;
  // 2. The receivers to the CPU (makeReferenceRequest reads both G-buffer textures back).
  const auto start = Clock::now();
  work.request = requestOf(frame, samplesOf(r));
  work.ms["readback"] = msSince(start);
  return work;
}

void finishReferenceFrame(const Scene& scene, const BenchResult& r, ReferenceFrameWork& work,
                          FrameTimes& times) {
  const bool rebuild = std::find(r.stages.begin(), r.stages.end(), "bvh_build") != r.stages.end();
  // 3. The BVH: every frame for a moving scene, else once per configuration and setup.
  auto start = Clock::now();
  if (!times.tracer || rebuild) {
    times.tracer = std::make_shared<ReferenceTracer>(scene);
    const double built = msSince(start);
    times.bvhMs.push_back(built);
    work.ms["bvh_build"] = built;
  }
  // 4. The trace (every core, as the stage `reference` traces).
  start = Clock::now();
  std::vector<float> visibility;
  if (!times.tracer->trace(work.request, visibility)) throw std::runtime_error(r.label + ": cancelled");
  work.ms["embree_trace"] = msSince(start);
  double total = 0;
  for (const std::string& stage : r.stages) {
    if (!work.ms.count(stage)) throw std::runtime_error(r.label + ": stage " + stage + " did not run");
    total += work.ms.at(stage);
    times.stages[stage].push_back(work.ms.at(stage));
  }
  times.totals.push_back(total);
}

void timeReferenceFrame(Pipeline& pipeline, Frame& frame, const BenchResult& r,
                        std::uint32_t frameKey, FrameTimes* times) {
  if (!times) return;
  ReferenceFrameWork work = prepareReferenceFrame(pipeline, frame, r, frameKey);
  finishReferenceFrame(frame.scene, r, work, *times);
}

#include "bench/bench_measure.h"

#include <algorithm>
#include <stdexcept>

#include "bench/bench_reference.h"
#include "core/pipeline.h"
#include "reference/reference_trace.h"

ParamSnapshot::ParamSnapshot(const Pipeline& pipeline) {
  for (const std::string& key : pipeline.paramKeys()) {
    Param& param = pipeline.param(key);
    values_.push_back({&param, param.value, param.automatic});
  }
}

void ParamSnapshot::restore() const {
  for (const Saved& saved : values_) {
    saved.param->value = saved.value;
    saved.param->automatic = saved.automatic;
  }
}

std::string applySets(Pipeline& pipeline, const std::vector<std::string>& sets) {
  for (const std::string& assignment : sets)
    if (std::string problem = pipeline.set(assignment); !problem.empty()) return problem;
  return "";
}

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::vector<std::string> timedStages(const Pipeline& pipeline, const std::string& method) {
  return pipeline.dependencies({pipeline.methodOutput(method)});
}

bool measureError(Pipeline& pipeline, Frame& frame, size_t setup, const BenchConfig& config,
                  int referenceSamples, BenchResult& r) {
  if (config.referenceSamples > 0)
    return measureReferenceError(pipeline, frame, setup, config, referenceSamples, r);
  // 1. What is measured.
  r = BenchResult{};
  r.setup = setup;
  r.label = config.label;
  r.method = config.method;
  r.family = config.family.empty() ? config.method : config.family;
  r.sets = config.sets;

  // 2. One frame against the ground truth, running only what the error image needs.
  const std::string errorMethod = pipeline.param("error.method").asEnum();
  if (errorMethod != config.method)
    throw std::runtime_error(config.label + ": error.method is " + errorMethod + ", not " +
                             config.method);
  pipeline.param("reference.enabled").value = 1;
  pipeline.set("reference.samples=" + std::to_string(referenceSamples));
  frame.frameKey = 0;
  pipeline.run(frame, {"error.absolute"});
  if (pipeline.hasStage("light")) r.map = frame.light.mapSize;  // light.resolution may be auto
  // The method's closure as this frame decided it (an `auto` choice, trace.hierarchy, is
  // decided while running) and every parameter of it.
  r.stages = timedStages(pipeline, config.method);
  for (const std::string& stage : r.stages)
    for (const Param& param : pipeline.stage(stage).params())
      r.params[stage + "." + param.key] = param.toString();
  const auto& c = frame.counters;
  if (c.count("reference.pending")) return false;
  if (!c.count("error.rmse"))
    throw std::runtime_error("no error metrics for " + config.label + " (reference missing)");
  r.error.rmse = c.at("error.rmse");
  r.error.max = c.at("error.max");
  r.error.meanAbsInShadow = c.at("error.meanAbsInShadow");
  r.error.p99 = c.at("error.p99");
  r.error.meanSigned = c.at("error.meanSigned");
  r.error.pixels = size_t(c.at("error.pixels"));
  r.error.pixelsInShadow = size_t(c.at("error.pixelsInShadow"));
  r.referenceSeconds = c.count("reference.seconds") ? c.at("reference.seconds") : 0.0;
  r.referenceCache = c.count("reference.cacheHit") ? int(c.at("reference.cacheHit")) : 0;
  // 3. The timed stages' counters (statistics such as trace.fetchesPerRay).
  for (const auto& [name, value] : c)
    if (std::find(r.stages.begin(), r.stages.end(), name.substr(0, name.find('.'))) != r.stages.end())
      r.counters[name] = value;
  pipeline.param("reference.enabled").value = 0;
  return true;
}

void timeFrame(Pipeline& pipeline, Frame& frame, const BenchResult& result, std::uint32_t frameKey,
               FrameTimes* times) {
  if (result.method == "reference") return timeReferenceFrame(pipeline, frame, result, frameKey, times);
  frame.frameKey = frameKey;
  pipeline.run(frame, {pipeline.methodOutput(result.method)});
  if (!times) return;
  double total = 0;
  for (const StageTime& time : pipeline.lastTimes()) {
    if (std::find(result.stages.begin(), result.stages.end(), time.stage) == result.stages.end())
      continue;
    if (!time.ran) throw std::runtime_error(result.label + ": stage " + time.stage + " did not run");
    total += time.milliseconds;
    times->stages[time.stage].push_back(time.milliseconds);
  }
  times->totals.push_back(total);
}

void summarize(const FrameTimes& times, BenchResult& r) {
  r.frames = int(times.totals.size());
  if (times.totals.empty()) return;
  r.msMedian = median(times.totals);
  r.msMin = *std::min_element(times.totals.begin(), times.totals.end());
  r.msMax = *std::max_element(times.totals.begin(), times.totals.end());
  for (const auto& [stage, values] : times.stages) r.stageMs[stage] = median(values);
  if (!times.bvhMs.empty()) {
    r.bvhMsMedian = median(times.bvhMs);
    r.bvhMsMax = *std::max_element(times.bvhMs.begin(), times.bvhMs.end());
  }
}

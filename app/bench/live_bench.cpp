#include "bench/live_bench.h"

#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "bench/bench_reference.h"
#include "core/frame.h"
#include "core/pipeline.h"
#include "gl/gpu_scene.h"

namespace {

void add(std::string& text, const glm::vec3& v) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "%a,%a,%a;", double(v.x), double(v.y), double(v.z));
  text += buffer;
}

}  // namespace

std::string sceneFingerprint(const Scene& scene) {
  std::string text = scene.name + ";" + std::to_string(scene.objects.size()) + ";" +
                     std::to_string(scene.triangleCount()) + ";";
  const Bounds bounds = scene.bounds();
  add(text, bounds.min), add(text, bounds.max);
  add(text, scene.light.center), add(text, scene.light.forward), add(text, scene.light.up);
  add(text, {scene.light.width, scene.light.height, 0});
  add(text, scene.camera.position), add(text, scene.camera.target), add(text, scene.camera.up);
  add(text, {scene.camera.fovYDegrees, 0, 0});
  return text;
}

BenchConfig currentConfig(const Pipeline& pipeline, const std::vector<BenchConfig>& preset) {
  std::string method = pipeline.param("composite.shadow").asEnum();
  if (method == "none") method = pipeline.param("error.method").asEnum();
  BenchConfig config{"current (" + method + ")", method, "current", {}};
  for (const std::string& stage : pipeline.dependencies({pipeline.methodOutput(method)}))
    for (const Param& param : pipeline.stage(stage).params())
      config.sets.push_back(stage + "." + param.key + "=" + param.toString());
  config.sets.push_back("composite.shadow=" + method);
  config.sets.push_back("error.method=" + method);
  std::string pixels = "error.pixels=" + pipeline.param("error.pixels").toString();
  for (const BenchConfig& each : preset)
    for (const std::string& set : each.sets)
      if (set.rfind("error.pixels=", 0) == 0) pixels = set;
  config.sets.push_back(pixels);
  return config;
}

int matchingResult(const std::vector<BenchResult>& results, const Pipeline& pipeline) {
  std::string method = pipeline.param("composite.shadow").asEnum();
  if (method == "none") method = pipeline.param("error.method").asEnum();
  for (size_t i = 0; i < results.size(); ++i) {
    const BenchResult& r = results[i];
    if (r.method != method || r.params.empty()) continue;
    bool same = true;
    for (const auto& [key, value] : r.params) {
      try {
        same = same && pipeline.param(key).toString() == value;
      } catch (const std::exception&) {
        same = false;  // a parameter this pipeline does not have
      }
    }
    if (same) return int(i);
  }
  return -1;
}

LiveBench::LiveBench() = default;
LiveBench::~LiveBench() { release(); }

void LiveBench::release() {
  if (tracing_.valid()) {  // its trace reads the scene: done (one frame's trace) before it goes
    tracing_.wait();
    tracing_ = {};
  }
  frame_.reset();  // before the pipeline it refers to; the reference's thread stops with it
  defaults_.reset();
  pipeline_.reset();
  gpuScene_.reset();
}

void LiveBench::start(const Scene& scene, const Pipeline& current, const LiveBenchOptions& options) {
  release();
  results_.clear();
  configs_.clear();
  next_ = 0, step_ = -1, waiting_ = false, times_ = {};
  options_ = options;
  scene_ = scene;
  fingerprint_ = sceneFingerprint(scene);
  auto pipeline = std::make_unique<Pipeline>();
  // 1. The plan: the preset's first setup (the others change the scene), then "current".
  const std::vector<BenchSetup> plan =
      makeBenchPlan(scene_, {options.preset, {}, options.width, options.height}, *pipeline);
  const BenchSetup& setup = plan.at(0);
  setupLabel_ = setup.label;
  configs_ = setup.configs;
  configs_.push_back(currentConfig(current, setup.configs));
  // 2. Every assignment checked before anything runs.
  const ParamSnapshot defaults(*pipeline);
  for (const BenchConfig& config : configs_) {
    if (std::string problem = applySets(*pipeline, config.sets); !problem.empty()) {
      configs_.clear();
      throw std::invalid_argument(config.label + ": " + problem);
    }
    defaults.restore();
  }
  pipeline_ = std::move(pipeline);
  defaults_ = std::make_unique<ParamSnapshot>(*pipeline_);
  gpuScene_ = std::make_unique<GpuScene>(scene_);
  frame_ = std::make_unique<Frame>(scene_, *gpuScene_, *pipeline_);
  frame_->eyeWidth = setup.width;
  frame_->eyeHeight = setup.height;
}

bool LiveBench::step() {
  if (!running()) return false;
  const BenchConfig& config = configs_[next_];
  defaults_->restore();
  applySets(*pipeline_, config.sets);
  pipeline_->set("reference.background=true");
  if (step_ < 0) {
    results_.resize(next_ + 1);
    waiting_ = !measureError(*pipeline_, *frame_, 0, config, options_.referenceSamples,
                             results_[next_]);
    if (!waiting_) step_ = 0;
    return true;
  }
  const BenchResult& result = results_[next_];
  if (result.method == "reference" && step_ >= options_.warmup) {
    // Its trace on a thread of its own; this step or a later one collects it.
    if (!tracing_.valid()) {
      auto work = std::make_shared<ReferenceFrameWork>(
          prepareReferenceFrame(*pipeline_, *frame_, result, std::uint32_t(1 + step_)));
      tracing_ = std::async(std::launch::async, [this, work, &result] {
        finishReferenceFrame(scene_, result, *work, times_);
      });
    }
    if (tracing_.wait_for(std::chrono::milliseconds(0)) != std::future_status::ready) return true;
    std::future<void> done = std::move(tracing_);
    done.get();  // rethrows a failure
  } else {
    timeFrame(*pipeline_, *frame_, result, std::uint32_t(1 + step_),
              step_ < options_.warmup ? nullptr : &times_);
  }
  if (++step_ == options_.warmup + options_.frames) {
    summarize(times_, results_[next_]);
    times_ = {};
    step_ = -1;
    if (++next_ == configs_.size()) release();
  }
  return running();
}

void LiveBench::cancel() {
  release();  // waits for a trace under way
  if (next_ < results_.size() && results_[next_].frames == 0) results_.pop_back();
  configs_.resize(next_);
}

float LiveBench::progress() const {
  if (configs_.empty()) return 0;
  const float perConfig = float(options_.warmup + options_.frames + 1);
  return std::min(1.0f, (float(next_) * perConfig + float(step_ + 1)) / (perConfig * float(configs_.size())));
}

std::string LiveBench::status() const {
  if (!running()) return results_.empty() ? "" : "measured " + std::to_string(results_.size()) + " configurations";
  std::string text = std::to_string(next_ + 1) + "/" + std::to_string(configs_.size()) + " " +
                     configs_[next_].label + ": ";
  if (step_ < 0) return text + (waiting_ ? "tracing the reference (Embree, background)" : "error frame");
  if (step_ < options_.warmup) return text + "warm-up frame";
  return text + "timed frame " + std::to_string(step_ - options_.warmup + 1) + "/" +
         std::to_string(options_.frames);
}

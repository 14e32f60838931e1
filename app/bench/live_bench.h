// The window's live speed-against-error measurement: the current scene's methods and
// configurations (a bench preset's first setup, plus the window's own parameters as one
// more configuration), measured one step per call so the window's main thread (which owns
// the GL context) keeps drawing, with progress and cancel. It has its own pipeline, GPU scene
// and frame, so the window's are untouched; its reference traces on a background thread
// (reference.background) and uses the disk cache as `penumbra bench` does. The reference as
// a method (bench/bench_reference.h) traces its timed frames on a thread of their own too:
// the step that starts one returns, later steps poll it.
#pragma once
#include <future>
#include <memory>
#include <string>
#include <vector>

#include "bench/bench_configs.h"
#include "bench/bench_measure.h"
#include "bench/bench_report.h"
#include "scene/scene.h"

class Pipeline;
struct Frame;
class GpuScene;

// What the measured points depend on besides the parameters: the scene's geometry, light
// and camera. Two scenes with the same fingerprint give the same images.
std::string sceneFingerprint(const Scene& scene);

// The configuration `pipeline` is in now: the method composite shows (error's when that is
// "none") with every parameter of the stages its visibility depends on. Its error counts the
// pixels `preset`'s configurations count (error.pixels; atty-4.2: the receivers), so one
// chart has one metric; the window's error.pixels where they set none.
BenchConfig currentConfig(const Pipeline& pipeline, const std::vector<BenchConfig>& preset = {});

// The result measured with exactly the method and parameters `pipeline` has now; -1 if none.
int matchingResult(const std::vector<BenchResult>& results, const Pipeline& pipeline);

struct LiveBenchOptions {
  std::string preset = "minimal";
  int width = 0, height = 0;  // 0: the preset's
  int frames = 5, warmup = 1;
  int referenceSamples = 16;
};

class LiveBench {
public:
  LiveBench();
  ~LiveBench();
  // Plans the run (throws std::invalid_argument for a bad preset or parameter); `current`
  // is the window's pipeline, whose configuration is measured last, as "current".
  void start(const Scene& scene, const Pipeline& current, const LiveBenchOptions& options);
  // One step: a configuration's error frame (or a poll of its pending reference), or one
  // timed frame. Returns whether more steps remain. Throws std::runtime_error on failure.
  bool step();
  void cancel();  // stops the reference's thread; keeps what was measured

  bool running() const { return next_ < configs_.size(); }
  float progress() const;     // 0..1 over every frame of the plan
  std::string status() const;  // "3/7 hierarchical 2L 2x2 map 512: timed frame 2/5"
  const std::vector<BenchResult>& results() const { return results_; }
  const std::string& fingerprint() const { return fingerprint_; }  // the scene measured
  const std::string& setupLabel() const { return setupLabel_; }
  int referenceSamples() const { return options_.referenceSamples; }  // the truth's m

private:
  void release();

  Scene scene_;
  std::unique_ptr<GpuScene> gpuScene_;
  std::unique_ptr<Pipeline> pipeline_;
  std::unique_ptr<Frame> frame_;
  std::unique_ptr<ParamSnapshot> defaults_;
  LiveBenchOptions options_;
  std::string fingerprint_, setupLabel_;
  std::vector<BenchConfig> configs_;
  std::vector<BenchResult> results_;
  size_t next_ = 0;       // the configuration being measured
  int step_ = -1;         // -1: its error frame; then warm-up and timed frames
  bool waiting_ = false;  // the reference is being traced
  FrameTimes times_;
  std::future<void> tracing_;  // the reference as a method: a timed frame's trace
};

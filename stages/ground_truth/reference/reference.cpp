// Stage `reference` (docs/design.md#ground-truth): the exact visibility every method is measured
// against, ray traced through the scene's real triangles on the CPU
// (app/reference/reference_trace.h explains the occluder set, the origin offset and the sampling),
// cached in memory and on disk (app/reference/reference_cache.h). Off by default: at 512x512 with
// 16x16 samples it costs seconds per new view on two cores (`penumbra export --set
// reference.enabled=true` prints the time); export, bench and the tests turn it on.
#include <chrono>
#include <cstdio>
#include <mutex>
#include <optional>
#include <thread>

#include "core/frame.h"
#include "core/run_control.h"
#include "reference/reference_cache.h"
#include "reference/reference_cost.h"
#include "reference/reference_request.h"
#include "reference/reference_trace.h"

ReferenceProgress& referenceStageProgress() {
  static ReferenceProgress progress;
  return progress;
}

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A hash of the occluders alone: the Embree scene is rebuilt only when they change.
std::string occluderKey(const Scene& scene) {
  ContentHash hash;
  for (const SceneObject& object : scene.objects) {
    if (object.receiverOnly) continue;
    hash.bytes(object.mesh.positions.data(), object.mesh.positions.size() * sizeof(glm::vec3));
    hash.bytes(object.mesh.indices.data(), object.mesh.indices.size() * sizeof(std::uint32_t));
  }
  return hash.hex();
}

class ReferenceStage final : public Stage {
public:
  ReferenceStage() {
    inputs_ = {
        Input::texture("wsPosition", "Receivers (G-buffer).", GL_RGBA32F),
        Input::texture("wsNormal", "Receiver normals (the ray origins' offset side).", GL_RGBA32F),
        Input::buffer("light", "The light frame (its CPU copy orients the light samples)."),
    };
    outputs_ = {{"visibility", "Exact visibility: the fraction of the m x m light samples that "
                               "the scene's real triangles do not hide (1 on the background).",
                 GL_R32F, {"visibility"}, {0, 0, 1, Colormap::Gray}, kRoleGroundTruth}};
    params_ = {
        Param::boolean("enabled", "Compute the ground truth (seconds per new view on the CPU; "
                                  "cached on disk, so an unchanged view is instant).", false),
        Param::integer("samples", "m: light samples per side, m x m rays per pixel.", 16, 1, 64),
        Param::choice("sampling", "stratified: one jittered sample per cell of the m x m grid "
                                  "(unbiased); uniform: the cell centres (a fixed quadrature), "
                                  "exactly the light samples of raster4d at raster4d.samples = m, "
                                  "so the two agree bit for bit up to ties at edges.",
                      {"stratified", "uniform"}, 0),
        Param::boolean("cache", "Reuse and store results under ~/.cache/penumbra/reference "
                                "($PENUMBRA_CACHE).", true),
        Param::integer("threads", "CPU threads tracing rows (0: every core).", 0, 0, 256),
        Param::real("budget", "Millions of ray steps a new reference image may take, estimated "
                              "before tracing (reference_cost.h: covered pixels x m^2 rays x "
                              "(1 + log2(1 + occluder triangles)), the BVH's depth); a run over "
                              "it is refused (the window asks). Cached images cost nothing. 0: "
                              "no limit.", 20000.0, 0.0, 1e9),
        Param::boolean("background", "Trace on a background thread and leave the output "
                                     "unwritten until done (for the window: it stays "
                                     "responsive and can cancel).", false),
    };
  }
  ~ReferenceStage() override { stopJob(); }
  std::string name() const override { return "reference"; }
  std::string summary() const override {
    return "Ground truth: visibility of the area light through the real triangles at m x m "
           "light samples per pixel, ray traced on the CPU (Embree), cached on disk. Off "
           "unless reference.enabled (bench turns it on).";
  }
  std::string thesisSection() const override { return "thesis §4 (ground truth)"; }

  void run(Frame& frame) override {
    const std::string key = "reference.visibility";
    if (!param("enabled").asBool()) {
      stopJob();
      frame.textures.erase(key);  // a stale truth must not be compared against
      return;
    }
    ReferenceRequest request = makeReferenceRequest(
        frame, frame.input(*this, "wsPosition"), frame.input(*this, "wsNormal"), param("samples").asInt(), param("sampling").asEnum() == "stratified");
    const std::string cacheKey = referenceCacheKey(frame.scene, request);
    frame.counters["reference.samples"] = double(request.samplesPerSide) * request.samplesPerSide;
    frame.counters["reference.seconds"] = 0;

    std::optional<std::vector<float>> visibility;
    if (cacheKey == memoryKey_) {
      visibility = memory_;
      frame.counters["reference.cacheHit"] = 1;  // memory
    } else if (param("cache").asBool() &&
               (visibility = loadCachedReference(cacheKey, request.width, request.height))) {
      frame.counters["reference.cacheHit"] = 2;  // disk
      remember(cacheKey, *visibility);
    } else {
      frame.counters["reference.cacheHit"] = 0;
      visibility = compute(frame, std::move(request), cacheKey);
    }
    if (visibility && job_ && job_->key != cacheKey) stopJob();  // back to a known view
    if (!visibility) {
      frame.textures.erase(key);  // pending (background) or cancelled
      return;
    }
    GlTexture& texture = frame.output(*this, "visibility", frame.eyeWidth, frame.eyeHeight);
    glTextureSubImage2D(texture.id(), 0, 0, 0, frame.eyeWidth, frame.eyeHeight, GL_RED, GL_FLOAT,
                        visibility->data());
  }

private:
  struct Job {
    std::thread thread;
    std::string key;
    std::vector<float> visibility;
    double seconds = 0;
    std::atomic<bool> done{false};
    bool completed = false;  // not cancelled
  };

  const ReferenceTracer& tracer(const Scene& scene) {
    const std::string key = occluderKey(scene);
    if (!tracer_ || key != tracerKey_) {
      tracer_ = std::make_shared<ReferenceTracer>(scene);
      tracerKey_ = key;
      ++tracerBuilds_;
    }
    return *tracer_;
  }

  void remember(const std::string& key, const std::vector<float>& visibility) {
    memoryKey_ = key;
    memory_ = visibility;
  }

  std::optional<std::vector<float>> compute(Frame& frame, ReferenceRequest request,
                                            const std::string& cacheKey) {
    tracer(frame.scene);
    // Embree's BVH is rebuilt only when an occluder moved (an animated scene's new pose), not
    // when only the camera or the light did: the builds so far, for people and tests.
    frame.counters["reference.bvhBuilds"] = tracerBuilds_;
    frame.counters["reference.occluderTriangles"] = double(tracer_->occluderTriangles());
    // Before tracing, its cost (reference_cost.h): refused over the budget (core/run_control.h).
    const ReferenceCostEstimate cost = estimateReferenceCost(request, tracer_->occluderTriangles());
    frame.counters["reference.estimatedRays"] = cost.rays;
    frame.counters["reference.estimatedSteps"] = cost.steps;
    if (!(job_ && job_->key == cacheKey)) {  // a job under way for this view was accepted
      char what[200];
      std::snprintf(what, sizeof what, "trace %.3g rays (%d x %d pixels x m^2 = %d samples) through "
                    "%zu occluder triangles, %.3g ray steps", cost.rays, request.width,
                    request.height, request.samplesPerSide * request.samplesPerSide,
                    tracer_->occluderTriangles(), cost.steps);
      checkRunBudget("reference.budget", cost.steps * 1e-6, param("budget").asFloat(), what,
                     "Lower reference.samples or the image size");
    }
    const std::uint64_t raysBefore = tracer_->raysCast();
    if (param("background").asBool()) return computeInBackground(frame, std::move(request), cacheKey);
    stopJob();
    ReferenceProgress& progress = referenceStageProgress();
    progress.cancel = false;
    progress.running = true;
    const auto start = std::chrono::steady_clock::now();
    std::vector<float> visibility;
    bool completed = false;
    {
      TerminalProgress bar("reference " + frame.scene.name + " " + std::to_string(request.width) +
                               "x" + std::to_string(request.height) + " m=" +
                               std::to_string(request.samplesPerSide), progress);
      std::atomic<bool> workerDone{false};
      std::exception_ptr failure;
      std::thread worker([&] {
        try {
          completed = tracer_->trace(request, visibility, &progress, param("threads").asInt());
        } catch (...) {
          failure = std::current_exception();
        }
        workerDone = true;
      });
      while (!workerDone) {
        bar.update();
        setRunProgress("in reference, tile " + std::to_string(progress.tilesDone) + " of " +
                       std::to_string(progress.tilesTotal));
        pollRunCancel();  // Esc or Cancel in the window (core/run_control.h): the tiles stop
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      worker.join();
      progress.running = false;
      if (failure) std::rethrow_exception(failure);
      bar.finish(secondsSince(start), !completed);
    }
    if (!completed) {  // reported as cancelled: nothing downstream runs, nothing is exported
      frame.counters["reference.cancelled"] = 1;
      const std::string why = runCancelRequested() ? runCancelReason() : "its own cancel";
      throw RunCancelled("cancelled in reference after " + std::to_string(progress.tilesDone) +
                         " of " + std::to_string(progress.tilesTotal) + " tiles (" + why + ")");
    }
    ++progress.finished;
    frame.counters["reference.raysCast"] = double(tracer_->raysCast() - raysBefore);
    return finish(frame, cacheKey, std::move(visibility), request, secondsSince(start));
  }

  std::vector<float> finish(Frame& frame, const std::string& cacheKey,
                            std::vector<float> visibility, const ReferenceRequest& request,
                            double seconds) {
    frame.counters["reference.seconds"] = seconds;
    if (param("cache").asBool())
      storeCachedReference(cacheKey, visibility, request, frame.scene.name, seconds);
    remember(cacheKey, visibility);
    return visibility;
  }

  std::optional<std::vector<float>> computeInBackground(Frame& frame, ReferenceRequest request,
                                                        const std::string& cacheKey) {
    if (job_ && job_->done) {
      job_->thread.join();
      auto job = std::move(job_);
      if (job->completed && job->key == cacheKey)
        return finish(frame, cacheKey, std::move(job->visibility), request, job->seconds);
    }
    if (job_ && job_->key == cacheKey) {
      frame.counters["reference.pending"] = 1;
      return std::nullopt;
    }
    stopJob();  // the inputs changed: the running job's answer is of no use
    ReferenceProgress& progress = referenceStageProgress();
    progress.cancel = false;
    progress.running = true;
    job_ = std::make_unique<Job>();
    job_->key = cacheKey;
    Job* job = job_.get();
    auto tracer = tracer_;
    const int threads = param("threads").asInt();
    job->thread = std::thread([job, tracer, threads, request = std::move(request), &progress] {
      const auto start = std::chrono::steady_clock::now();
      job->completed = tracer->trace(request, job->visibility, &progress, threads);
      job->seconds = secondsSince(start);
      progress.running = false;
      if (job->completed) ++progress.finished;
      job->done = true;
    });
    frame.counters["reference.pending"] = 1;
    return std::nullopt;
  }

  void stopJob() {
    if (!job_) return;
    referenceStageProgress().cancel = true;
    job_->thread.join();
    job_.reset();
    referenceStageProgress().cancel = false;
  }

  std::shared_ptr<ReferenceTracer> tracer_;
  std::string tracerKey_;
  int tracerBuilds_ = 0;
  std::string memoryKey_;
  std::vector<float> memory_;
  std::unique_ptr<Job> job_;
};

}  // namespace

std::unique_ptr<Stage> makeReferenceStage() { return std::make_unique<ReferenceStage>(); }

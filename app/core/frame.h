// Everything one run of the pipeline reads and writes: the scene on the GPU, the camera
// uniforms, and every stage output by name ("stage.output"). Stages read only their own
// declared input slots (input(), inputBuffer()); views, export and tests read outputs by
// name (texture()).
#pragma once
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>

#include "core/stage.h"
#include "gl/gl_texture.h"
#include "gl/gpu_layout.h"
#include "gl/gpu_scene.h"
#include "scene/light_frame.h"

class Pipeline;

struct Frame {
  const Scene& scene;
  const GpuScene& gpuScene;
  const Pipeline& pipeline;  // resolves input slots to producers; not for reading parameters
  int eyeWidth = 512, eyeHeight = 512;
  std::uint32_t frameKey = 0;  // scrambles the hash per frame (thesis Appendix A "key")
  // The window's timeline is playing this run (set by the window's run only; false for every
  // export, script, lesson, bench and CLI run): a stage may keep a policy choice it made at an
  // earlier pose instead of deciding it again (light.auto_while_playing).
  bool timelinePlaying = false;
  // CPU copy of the `light` stage's output (written by that stage; for the CPU-side readers:
  // reference, views, the trace panel).
  LightFrame light{};
  gpu::FrameUniforms uniforms{};
  GlBuffer uniformBuffer;

  std::map<std::string, GlTexture> textures;  // "stage.output"
  std::map<std::string, double> counters;     // statistics for people: "trace.rays", ...
  // One sentence per `auto` parameter decided this run (the light stage's choices, then the
  // pipeline's choice slots); the numbers behind them are the light stage's
  // (stages/shared_inputs/light/auto_settings.h).
  std::vector<std::string> autoReasons;
  // CPU copies of GPU data a stage read back after the run (Frame::readAfterFrame), by
  // "stage.name": the bytes as the stage's layout header lays them out (the trace's recorded
  // steps: "trace.steps", read through stages/monte_carlo/trace/trace_steps.h).
  std::map<std::string, std::vector<unsigned char>> readBack;
  std::map<std::string, std::unique_ptr<GlBuffer>> buffers;  // buffer outputs, "stage.output"
  // Demand (docs/decisions/014-outputs-nobody-asked-for.md): the outputs this run was asked for
  // (Pipeline::run; empty: all), and those a stage wrote only where the stages after it read them
  // because nobody asked for them (the N-buffer's texels that repeat a border window): inputs to
  // the stages after, not outputs to show or export: has() and texture() treat them as not written.
  std::set<std::string> requested;
  std::set<std::string> partial;

  // Counts the GPU wrote into buffers, read back after the last stage of the run
  // (Pipeline::run, all at once), so no stage waits for the GPU inside the frame: a stage
  // asks for `bytes` at `offset` of `buffer` and gets them in `use`, which fills counters
  // (or readBack). The buffer must outlive the run (a stage's own member, or an output).
  struct Readback {
    GLuint buffer;
    GLintptr offset;
    GLsizeiptr bytes;
    std::function<void(const std::vector<unsigned char>& bytes, Frame& frame)> use;
  };
  std::vector<Readback> readbacks;
  void readAfterFrame(const GlBuffer& buffer, GLintptr offset, GLsizeiptr bytes,
                      std::function<void(const std::vector<unsigned char>&, Frame&)> use) {
    readbacks.push_back({buffer.id(), offset, bytes, std::move(use)});
  }
  // Does the queued read-backs (the one wait for the GPU) and empties the queue: the end of
  // Pipeline::run, or a test that runs one stage alone.
  void finishReadbacks();

  Frame(const Scene& scene, const GpuScene& gpuScene, const Pipeline& pipeline)
      : scene(scene), gpuScene(gpuScene), pipeline(pipeline) {}

  // Allocates (or reuses, when the shape matches) the texture of a declared output; `levels`
  // mip levels (the min-max mipmap; every other output has one).
  GlTexture& output(const Stage& stage, const std::string& name, int width, int height,
                    int layers = 0, int levels = 1);
  // The storage buffer of a declared buffer output (created empty on first use).
  GlBuffer& outputBuffer(const Stage& stage, const std::string& name);
  // The texture wired to `slot` of `stage`; throws naming the slot and producer if the
  // producer has not written it this run.
  const GlTexture& input(const Stage& stage, const std::string& slot) const;
  const GlBuffer& inputBuffer(const Stage& stage, const std::string& slot) const;
  // Whether `slot` is wired and written this run (false for a choice slot set to "none").
  bool connected(const Stage& stage, const std::string& slot) const;

  // An output by name, for views, export and tests; throws naming what is missing.
  const GlTexture& texture(const std::string& stageDotOutput) const;
  bool has(const std::string& stageDotOutput) const {
    return textures.count(stageDotOutput) > 0 && partial.count(stageDotOutput) == 0;
  }
  // Whether the caller of this run asked for an output (to show or export it).
  bool wanted(const std::string& stageDotOutput) const {
    return requested.empty() || requested.count(stageDotOutput) > 0;
  }
  // MiB of an output written this run (texture: from its format and size; buffer: its
  // allocated size); 0 when not written.
  double megabytes(const std::string& stageDotOutput) const;
  // Sum over the outputs of `stage`.
  double megabytes(const Stage& stage) const;
};

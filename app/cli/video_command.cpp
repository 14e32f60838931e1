#include "cli/video_command.h"

#include <cstdio>
#include <filesystem>

#include "base/input_error.h"
#include "cli/export_command.h"
#include "export/video_export.h"
#include "io/headless_session.h"
#include "scene/animation.h"
#include "scene/scene_builtin.h"

int runVideoExport(const ExportOptions& options) {
  // 1. Everything that can be checked before any work: the range, the outputs, ffmpeg, --out.
  VideoRequest request;
  request.range = parseVideoRange(options.timeRange, options.fps);
  request.outputs = options.outputs.empty() ? std::vector<std::string>{"composite.color"} : options.outputs;
  request.sideBySide = options.sideBySide;
  request.encode = !options.framesOnly;
  {
    const Pipeline declared;  // the declarations alone: no GL
    checkVideoRequest(request, declared, "--outputs");
  }
  if (request.encode && ffmpegPath().empty()) throw InputError(missingFfmpegMessage());
  checkOutputDirectory(options.outDirectory, "--out", "run.json");
  std::vector<std::string> warnings;
  const Scene rest = loadScene(options.scene, warnings);  // the scene at rest, posed per frame
  for (int frame = 0; frame < request.range.frames(); ++frame)  // cheap next to the frames
    if (std::string problem = posedSceneProblem(rest, request.range.time(frame)); !problem.empty())
      throw InputError(printable(options.scene, 200) + " at t = " + std::to_string(request.range.time(frame)) +
                       " s: " + problem);
  HeadlessSession session;
  if (int status = session.open("export", options.scene, options.sets, options.width, options.height,
                                request.range.start))
    return status;
  if (rest.animation.empty())
    std::fprintf(stderr, "warning: scene '%s' is not animated: every frame is the same image\n",
                 printable(session.scene.name).c_str());
  // 2. The frames, each from the scene posed at its time (decision 090), then the videos.
  VideoExport exporter(options.outDirectory, request, session.pipeline);
  for (int frame = 0; frame < exporter.frames(); ++frame) {
    if (frame > 0) {
      session.frame.reset();
      session.gpuScene.reset();
      session.scene = poseAt(rest, exporter.time(frame));
      session.gpuScene = std::make_unique<GpuScene>(session.scene);
      session.frame = std::make_unique<Frame>(session.scene, *session.gpuScene, session.pipeline);
      session.frame->eyeWidth = options.width;
      session.frame->eyeHeight = options.height;
    }
    session.frame->frameKey = options.frameKey;  // the same key every frame (no swimming noise)
    session.pipeline.run(*session.frame, exporter.outputs());
    exporter.writeFrame(frame, *session.frame);
  }
  nlohmann::json run;
  run["scene"] = session.scene.name;
  run["renderer"] = session.context->renderer();
  run["eye_size"] = {options.width, options.height};
  run["frame_key"] = options.frameKey;
  run["triangles"] = session.scene.triangleCount();
  size_t frameFiles = 0;
  const auto written = exporter.finish(run, frameFiles);
  std::printf("penumbra export: scene '%s', %d frames at %g fps (t = %g .. %g s, end exclusive) on %s\n",
              printable(session.scene.name).c_str(), exporter.frames(), request.range.fps,
              request.range.start, request.range.end, session.context->renderer().c_str());
  for (const std::string& path : written) std::printf("  %s\n", path.c_str());
  std::printf("wrote %zu frame files and %zu more files into %s\n", frameFiles, written.size(),
              std::filesystem::absolute(options.outDirectory).c_str());
  return 0;
}

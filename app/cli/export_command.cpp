#include "cli/export_command.h"

#include <cstdio>
#include <filesystem>

#include "base/input_error.h"
#include "cli/interrupt.h"
#include "cli/progress_line.h"
#include "cli/video_command.h"
#include "export/frame_export.h"
#include "io/headless_session.h"
#include "io/output_path.h"

int runExport(const ExportOptions& options) {
  const CliProgress progress("export");  // a bar on stderr for an export past a second
  const InterruptCancels interrupts;      // Ctrl-C: stop at the next check, nothing written
  if (!options.timeRange.empty()) return runVideoExport(options);
  checkOutputDirectory(options.outDirectory, "--out", "run.json");  // before any rendering
  HeadlessSession session;
  if (int status = session.open("export", options.scene, options.sets, options.width, options.height,
                                options.time))
    return status;
  Frame& frame = *session.frame;
  frame.frameKey = options.frameKey;
  session.pipeline.run(frame);
  const std::string renderer = session.context->renderer();
  std::string keyParameters;
  for (const std::string& set : options.sets) keyParameters += (keyParameters.empty() ? "" : ", ") + set;
  const auto written = exportFrame(options.outDirectory, frame, session.pipeline, renderer,
                                   options.annotate, keyParameters);
  std::printf("penumbra export: scene '%s' (%zu triangles) on %s\n",
              printable(session.scene.name).c_str(), session.scene.triangleCount(), renderer.c_str());
  for (const StageTime& time : session.pipeline.lastTimes())
    std::printf("  %-14s %8.2f ms\n", time.stage.c_str(), time.milliseconds);
  std::printf("wrote %zu files into %s\n", written.size(),
              std::filesystem::absolute(options.outDirectory).c_str());
  // An empty frame (no receiver pixel) is the scene's or the camera's fault: the files are
  // written (to look at), and the exit status is 2 as for any bad input (docs/accuracy.md).
  const std::vector<float> positions = frame.texture("gbuffer.wsPosition").readFloats();
  size_t covered = 0;
  for (size_t i = 3; i < positions.size(); i += 4) covered += positions[i] != 0;
  if (covered == 0) {
    std::fprintf(stderr, "penumbra export: ERROR: the frame has no covered pixel: the camera "
                         "of scene '%s' sees no geometry (exit status 2)\n",
                 printable(session.scene.name).c_str());
    return 2;
  }
  return 0;
}

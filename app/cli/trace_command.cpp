#include "cli/trace_command.h"

#include <cstdio>
#include <filesystem>

#include "export/trace_json.h"
#include "io/headless_session.h"
#include "io/image_export.h"
#include "io/output_path.h"
#include "monte_carlo/trace/trace_steps.h"

int runTraceCommand(const TraceOptions& options) {
  int x = -1, y = -1;
  char extra = 0;
  if (std::sscanf(options.pixel.c_str(), "%d,%d%c", &x, &y, &extra) != 2 || x < 0 || y < 0 ||
      x >= options.width || y >= options.height) {
    std::fprintf(stderr, "penumbra trace: --pixel '%s' must be X,Y inside the %dx%d image\n",
                 options.pixel.c_str(), options.width, options.height);
    return 2;
  }
  if (!options.out.empty()) checkOutputFile(options.out, "--out");  // before any rendering
  std::vector<std::string> sets = options.sets;
  sets.push_back("trace.record_x=" + std::to_string(x));
  sets.push_back("trace.record_y=" + std::to_string(y));
  HeadlessSession session;
  if (int status = session.open("trace", options.scene, sets, options.width, options.height,
                                options.time))
    return status;
  session.pipeline.run(*session.frame);
  const std::string json = traceStepsJson(*session.frame, x, y);
  if (options.out.empty()) {
    std::fputs(json.c_str(), stdout);
    return 0;
  }
  const std::filesystem::path out(options.out);
  if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
  writeTextFile(out, json);
  std::printf("penumbra trace: %zu steps written to %s\n", recordedTraceSteps(*session.frame).size(),
              options.out.c_str());
  return 0;
}

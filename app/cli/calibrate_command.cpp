#include "cli/calibrate_command.h"

#include <cstdio>
#include <string>

#include "gl/gl_context.h"
#include "gl/renderer_calibration.h"
#include "io/renderer_calibration_measure.h"

int runCalibrateCommand(const CalibrateOptions& options) {
  std::string error;
  const std::unique_ptr<GlContext> context = GlContext::createHeadless(error);
  if (!context) {
    std::fprintf(stderr, "penumbra calibrate: %s\n", error.c_str());
    return 1;
  }
  if (int status = applyRendererCalibration("calibrate", options.refresh ? "refresh" : ""))
    return status;
  const RendererCalibration calibration = activeRendererCalibration();
  std::printf("%s\n", calibration.describe().c_str());
  if (calibration.source == "measured" || calibration.source == "cached") {
    std::printf("  map build: %.3g ms per texel-level; trace: %.3g ms per pixel and ray\n",
                calibration.buildMsPerTexelLevel, calibration.traceMsPerPixelRay);
    std::printf("  N-buffer's extra build: %.3g ms per texel-level; min-max's extra eye cost: "
                "%.3g ms per pixel\n",
                calibration.nbufferExtraMsPerTexelLevel, calibration.minmaxExtraMsPerEyePixel);
  }
  return 0;
}

// `penumbra calibrate [--refresh]`: the crossovers `auto` uses on this renderer
// (gl/renderer_calibration.h): prints the calibration in use and its file, measuring it when
// the cache holds none (or, --refresh, always; the cache rewritten). PENUMBRA_CALIBRATION
// applies as everywhere (fallback: the constants, nothing measured).
#pragma once

struct CalibrateOptions {
  bool refresh = false;
};

int runCalibrateCommand(const CalibrateOptions& options);

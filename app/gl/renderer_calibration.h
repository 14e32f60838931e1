// `auto` per renderer: the two crossovers `auto` weighs costs with, measured on the renderer
// it runs on (docs/decisions/071-auto-calibrated-per-renderer.md).
//  - texelLevelsPerPixelRay: how many texel-levels of map build (light layers + N-buffer)
//    cost as much as one ray for one eye pixel (the map resolution's budget,
//    app/scene/auto_settings.h);
//  - nbufferTexelLevelsPerEyePixel: N-buffer texel-levels per eye pixel above which the
//    min-max mipmap's cheaper build outweighs its looser bounds over the eye (the trace's
//    `auto` hierarchy, stages/monte_carlo/trace/trace.cpp).
// A short calibration measures both at first use on a renderer (renderer_calibration_measure.h)
// and caches them in $XDG_CACHE_HOME/penumbra (else ~/.cache/penumbra), one file per
// renderer, keyed by GL_RENDERER and GL_VERSION (which names the driver's version).
// PENUMBRA_CALIBRATION chooses (`penumbra calibrate` and the window's button refresh):
//   unset or "cached"  the cached calibration, measured first where there is none;
//   "refresh"          measured again, the cache rewritten;
//   "fallback"         the constants below, nothing measured or read (the tests: outputs that
//                      do not depend on how loaded the machine is);
//   a file path        that calibration file, pinned (its renderer is not checked).
#pragma once
#include <functional>
#include <optional>
#include <string>

// Measured on llvmpipe (the constants `auto` used before calibration existed; where they come
// from: app/scene/auto_settings.h and docs/decisions/027-auto-hierarchy-rule.md).
inline constexpr double kFallbackTexelLevelsPerPixelRay = 8.0;
inline constexpr double kFallbackNBufferTexelLevelsPerEyePixel = 12.0;

struct RendererCalibration {
  // "fallback" (the constants), "measured" (this process), "cached" (read from the cache),
  // "pinned" (a file named by PENUMBRA_CALIBRATION).
  std::string source = "fallback";
  std::string renderer;   // GL_RENDERER
  std::string glVersion;  // GL_VERSION
  std::string measuredAt;  // UTC, ISO 8601; "" for the fallback
  std::string file;        // the file it was read from or written to; "" if none
  double texelLevelsPerPixelRay = kFallbackTexelLevelsPerPixelRay;
  double nbufferTexelLevelsPerEyePixel = kFallbackNBufferTexelLevelsPerEyePixel;
  // The timings the values came from (ms per unit), for people reading the file.
  double buildMsPerTexelLevel = 0, traceMsPerPixelRay = 0;
  double nbufferExtraMsPerTexelLevel = 0, minmaxExtraMsPerEyePixel = 0;
  std::string notes;  // what the measurement could not resolve (a constant kept), or ""

  // One line for the inspector, run.json and the log.
  std::string describe() const;
};

// The cache key of a renderer: GL_RENDERER and GL_VERSION joined, every byte outside
// [A-Za-z0-9._-] replaced by '_' (a file name on every system), and an FNV-1a hash of the
// exact strings so two renderers that differ only in replaced bytes never share a file.
std::string calibrationKey(const std::string& renderer, const std::string& glVersion);
// The cache directory: $XDG_CACHE_HOME/penumbra, else $HOME/.cache/penumbra; "" when neither
// variable is set (then nothing is cached).
std::string calibrationCacheDirectory();
// The cache file of a renderer in `directory`: calibration-<key>.json.
std::string calibrationCachePath(const std::string& directory, const std::string& renderer,
                                 const std::string& glVersion);

// The file's text: JSON, every field of RendererCalibration but source and file.
std::string calibrationToJson(const RendererCalibration& calibration);
// Reads a calibration file's text. Rejects (nullopt, the reason in `problem`) anything that is
// not exactly such a file: not JSON, another format or version, a field missing or of the
// wrong type, a crossover not finite or outside [kMinCrossover, kMaxCrossover], and, when
// `renderer` / `glVersion` are given (not null), a file written for another renderer.
inline constexpr double kMinCrossover = 0.01, kMaxCrossover = 1e5;
std::optional<RendererCalibration> calibrationFromJson(const std::string& text,
                                                       std::string& problem,
                                                       const std::string* renderer = nullptr,
                                                       const std::string* glVersion = nullptr);

// What PENUMBRA_CALIBRATION (or `override`, when not empty) asks for.
enum class CalibrationMode { Cached, Refresh, Fallback, Pinned };
struct CalibrationRequest {
  CalibrationMode mode = CalibrationMode::Cached;
  std::string file;  // Pinned
};
CalibrationRequest calibrationRequest(const std::string& override = "");

// Measures the crossovers on the current context (renderer_calibration_measure.h); the
// result's source, renderer, version and time are filled by resolveRendererCalibration.
using CalibrationMeasure = std::function<RendererCalibration()>;
// The calibration for the current GL context (renderer and version read from it): the
// request followed; a cache file that is missing or rejected is measured again and rewritten
// (written to a temporary file and renamed: never half-written). A measurement with a
// crossover left unresolved (notes) is used but not cached. `log` gets one line per
// thing done. Throws std::invalid_argument for a pinned file that cannot be read or is rejected.
RendererCalibration resolveRendererCalibration(const CalibrationRequest& request,
                                               const CalibrationMeasure& measure,
                                               std::string* log = nullptr);

// The calibration `auto` uses in this process: the fallback until one is set (a pipeline
// run without a session, as most GL tests do, uses the constants). A copy: thread-safe.
RendererCalibration activeRendererCalibration();
void setActiveRendererCalibration(const RendererCalibration& calibration);
// Counts setActiveRendererCalibration calls: a run key that includes it re-runs `auto` after
// a recalibration (the window).
int rendererCalibrationGeneration();
// The window's "measure again" button: asks the frame loop to recalibrate before its next run.
void requestRecalibration();
bool takeRecalibrationRequest();  // true once per request

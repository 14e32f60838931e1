#include "gl/renderer_calibration.h"

#include <epoxy/gl.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace {

constexpr const char* kFormat = "penumbra-renderer-calibration";
constexpr int kVersion = 1;

std::string glString(GLenum name) {
  const auto* text = reinterpret_cast<const char*>(glGetString(name));
  return text ? text : "";
}

std::string utcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

std::string readText(const std::string& path, bool& ok) {
  std::ifstream in(path, std::ios::binary);
  ok = bool(in);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Written beside the target and renamed over it: a reader sees the old file or the new one.
bool writeAtomically(const std::string& path, const std::string& text, std::string& problem) {
  std::error_code error;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), error);
  if (error) {
    problem = "cannot create " + std::filesystem::path(path).parent_path().string() + ": " + error.message();
    return false;
  }
  const std::string temporary = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) {
      problem = "cannot write " + temporary;
      std::filesystem::remove(temporary, error);
      return false;
    }
  }
  std::filesystem::rename(temporary, path, error);
  if (error) {
    problem = "cannot rename " + temporary + " to " + path + ": " + error.message();
    std::filesystem::remove(temporary, error);
    return false;
  }
  return true;
}

std::mutex activeMutex;
RendererCalibration active;  // the fallback until set
std::atomic<int> generation{0};
std::atomic<bool> recalibrationRequested{false};

}  // namespace

std::string RendererCalibration::describe() const {
  char values[160];
  std::snprintf(values, sizeof values,
                "%.3g texel-levels of map build per pixel-ray, N-buffer above %.3g texel-levels "
                "per eye pixel",
                texelLevelsPerPixelRay, nbufferTexelLevelsPerEyePixel);
  std::string text;
  if (source == "fallback")
    text = "fallback (the constants measured on llvmpipe, nothing measured here): ";
  else if (source == "pinned")
    text = "pinned (" + file + ", measured on " + renderer + " at " + measuredAt + "): ";
  else
    text = source + " on " + renderer + " (" + glVersion + ") at " + measuredAt +
           (file.empty() ? "" : ", " + file) + ": ";
  text += values;
  if (!notes.empty()) text += "; " + notes;
  return text;
}

std::string calibrationKey(const std::string& renderer, const std::string& glVersion) {
  const std::string joined = renderer + "|" + glVersion;
  std::uint64_t hash = 1469598103934665603ull;
  for (unsigned char byte : joined) hash = (hash ^ byte) * 1099511628211ull;
  std::string key;
  for (char c : joined) {
    const bool plain = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') ||
                       (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '_';
    key += plain ? c : '_';
  }
  if (key.size() > 96) key.resize(96);  // well under every file system's name limit
  char suffix[20];
  std::snprintf(suffix, sizeof suffix, "-%016llx", static_cast<unsigned long long>(hash));
  return key + suffix;
}

std::string calibrationCacheDirectory() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return (std::filesystem::path(xdg) / "penumbra").string();
  if (const char* home = std::getenv("HOME"); home && *home)
    return (std::filesystem::path(home) / ".cache" / "penumbra").string();
  return "";
}

std::string calibrationCachePath(const std::string& directory, const std::string& renderer,
                                 const std::string& glVersion) {
  return (std::filesystem::path(directory) /
          ("calibration-" + calibrationKey(renderer, glVersion) + ".json")).string();
}

std::string calibrationToJson(const RendererCalibration& c) {
  nlohmann::json json = {
      {"format", kFormat},
      {"version", kVersion},
      {"renderer", c.renderer},
      {"gl_version", c.glVersion},
      {"measured_at", c.measuredAt},
      {"texel_levels_per_pixel_ray", c.texelLevelsPerPixelRay},
      {"nbuffer_texel_levels_per_eye_pixel", c.nbufferTexelLevelsPerEyePixel},
      {"build_ms_per_texel_level", c.buildMsPerTexelLevel},
      {"trace_ms_per_pixel_ray", c.traceMsPerPixelRay},
      {"nbuffer_extra_ms_per_texel_level", c.nbufferExtraMsPerTexelLevel},
      {"minmax_extra_ms_per_eye_pixel", c.minmaxExtraMsPerEyePixel},
      {"notes", c.notes},
  };
  return json.dump(2) + "\n";
}

std::optional<RendererCalibration> calibrationFromJson(const std::string& text,
                                                       std::string& problem,
                                                       const std::string* renderer,
                                                       const std::string* glVersion) {
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded()) return problem = "not JSON", std::nullopt;
  if (!json.is_object()) return problem = "not a JSON object", std::nullopt;
  const auto string = [&](const char* key, std::string& out) {
    const auto found = json.find(key);
    if (found == json.end() || !found->is_string()) {
      problem = std::string("\"") + key + "\" missing or not a string";
      return false;
    }
    out = found->get<std::string>();
    return true;
  };
  const auto number = [&](const char* key, double& out, double low, double high) {
    const auto found = json.find(key);
    if (found == json.end() || !found->is_number()) {
      problem = std::string("\"") + key + "\" missing or not a number";
      return false;
    }
    out = found->get<double>();
    if (!std::isfinite(out) || out < low || out > high) {
      char text[160];
      std::snprintf(text, sizeof text, "\"%s\" is %g, outside [%g, %g]", key, out, low, high);
      problem = text;
      return false;
    }
    return true;
  };
  std::string format;
  if (!string("format", format)) return std::nullopt;
  if (format != kFormat) return problem = "\"format\" is not \"" + std::string(kFormat) + "\"", std::nullopt;
  const auto version = json.find("version");
  if (version == json.end() || !version->is_number_integer() || version->get<long long>() != kVersion)
    return problem = "\"version\" is not " + std::to_string(kVersion), std::nullopt;
  RendererCalibration c;
  c.source = "cached";
  const double inf = HUGE_VAL;
  if (!string("renderer", c.renderer) || !string("gl_version", c.glVersion) ||
      !string("measured_at", c.measuredAt) || !string("notes", c.notes) ||
      !number("texel_levels_per_pixel_ray", c.texelLevelsPerPixelRay, kMinCrossover, kMaxCrossover) ||
      !number("nbuffer_texel_levels_per_eye_pixel", c.nbufferTexelLevelsPerEyePixel, kMinCrossover,
              kMaxCrossover) ||
      !number("build_ms_per_texel_level", c.buildMsPerTexelLevel, -inf, inf) ||
      !number("trace_ms_per_pixel_ray", c.traceMsPerPixelRay, -inf, inf) ||
      !number("nbuffer_extra_ms_per_texel_level", c.nbufferExtraMsPerTexelLevel, -inf, inf) ||
      !number("minmax_extra_ms_per_eye_pixel", c.minmaxExtraMsPerEyePixel, -inf, inf))
    return std::nullopt;
  if (renderer && c.renderer != *renderer)
    return problem = "written for renderer \"" + c.renderer + "\", not \"" + *renderer + "\"", std::nullopt;
  if (glVersion && c.glVersion != *glVersion)
    return problem = "written for GL_VERSION \"" + c.glVersion + "\", not \"" + *glVersion + "\"", std::nullopt;
  return c;
}

CalibrationRequest calibrationRequest(const std::string& override) {
  std::string value = override;
  if (value.empty())
    if (const char* env = std::getenv("PENUMBRA_CALIBRATION")) value = env;
  if (value.empty() || value == "cached") return {CalibrationMode::Cached, ""};
  if (value == "refresh") return {CalibrationMode::Refresh, ""};
  if (value == "fallback") return {CalibrationMode::Fallback, ""};
  return {CalibrationMode::Pinned, value};
}

RendererCalibration resolveRendererCalibration(const CalibrationRequest& request,
                                               const CalibrationMeasure& measure,
                                               std::string* log) {
  const auto note = [&](const std::string& line) {
    if (log) *log += line + "\n";
  };
  if (request.mode == CalibrationMode::Fallback) return RendererCalibration{};  // silent: the tests' mode
  if (request.mode == CalibrationMode::Pinned) {
    bool ok;
    const std::string text = readText(request.file, ok);
    if (!ok)
      throw std::invalid_argument("PENUMBRA_CALIBRATION=" + request.file +
                               ": cannot read the file (the values: cached, refresh, fallback, "
                               "or a calibration file)");
    std::string problem;
    std::optional<RendererCalibration> pinned = calibrationFromJson(text, problem);
    if (!pinned)
      throw std::invalid_argument("PENUMBRA_CALIBRATION=" + request.file +
                               ": not a calibration file: " + problem);
    pinned->source = "pinned";
    pinned->file = request.file;
    note("calibration: pinned to " + request.file);
    return *pinned;
  }
  const std::string renderer = glString(GL_RENDERER), version = glString(GL_VERSION);
  const std::string directory = calibrationCacheDirectory();
  const std::string path = directory.empty() ? "" : calibrationCachePath(directory, renderer, version);
  if (request.mode == CalibrationMode::Cached && !path.empty()) {
    bool ok;
    const std::string text = readText(path, ok);
    if (ok) {
      std::string problem;
      if (std::optional<RendererCalibration> cached =
              calibrationFromJson(text, problem, &renderer, &version)) {
        cached->file = path;
        return *cached;
      }
      note("calibration: " + path + " rejected (" + problem + "): measuring again");
    }
  }
  RendererCalibration measured = measure();
  measured.source = "measured";
  measured.renderer = renderer;
  measured.glVersion = version;
  measured.measuredAt = utcNow();
  if (path.empty()) {
    note("calibration: neither XDG_CACHE_HOME nor HOME is set: not cached");
  } else if (!measured.notes.empty()) {
    // A crossover the timings could not resolve (a loaded machine): this process uses the
    // constant, the next one measures again.
    note("calibration: measured, not cached: " + measured.notes);
  } else if (std::string problem; writeAtomically(path, calibrationToJson(measured), problem)) {
    measured.file = path;
    note("calibration: measured, cached in " + path);
  } else {
    note("calibration: measured, not cached: " + problem);
  }
  return measured;
}

RendererCalibration activeRendererCalibration() {
  const std::lock_guard<std::mutex> lock(activeMutex);
  return active;
}

void setActiveRendererCalibration(const RendererCalibration& calibration) {
  const std::lock_guard<std::mutex> lock(activeMutex);
  active = calibration;
  ++generation;
}

int rendererCalibrationGeneration() { return generation.load(); }
void requestRecalibration() { recalibrationRequested = true; }
bool takeRecalibrationRequest() { return recalibrationRequested.exchange(false); }

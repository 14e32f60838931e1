// `auto` per renderer (app/gl/renderer_calibration.h): the cache key, the cache file's reader
// (bad content rejected with a reason, never half-read), the modes (fallback, cached, refresh,
// pinned), that the crossover is what `auto` uses, and the command line's side. Every test
// here pins or fakes the measurement except CalibrateCommandMeasuresThenReadsTheCache, which
// asserts only what does not depend on the machine's load.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

#include "gl/renderer_calibration.h"
#include "scene/scene_builtin.h"
#include "support/command.h"
#include "support/gl_test.h"
#include "support/temp_directory.h"

namespace {

// Sets an environment variable for one scope, restoring the previous value.
class ScopedEnv {
public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) had_ = true, old_ = old;
    if (value) setenv(name, value, 1);
    else unsetenv(name);
  }
  ~ScopedEnv() {
    if (had_) setenv(name_, old_.c_str(), 1);
    else unsetenv(name_);
  }

private:
  const char* name_;
  bool had_ = false;
  std::string old_;
};

RendererCalibration sample() {
  RendererCalibration c;
  c.source = "measured";
  c.renderer = "Some GPU/PCIe/SSE2";
  c.glVersion = "4.6.0 NVIDIA 535.0";
  c.measuredAt = "2026-01-02T03:04:05Z";
  c.texelLevelsPerPixelRay = 23;
  c.nbufferTexelLevelsPerEyePixel = 3.5;
  c.buildMsPerTexelLevel = 1e-7;
  c.traceMsPerPixelRay = 2.3e-6;
  c.nbufferExtraMsPerTexelLevel = 4e-8;
  c.minmaxExtraMsPerEyePixel = 1.4e-7;
  return c;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

TEST(RendererCalibration, KeyIsAFileNameAndTellsRenderersApart) {
  const std::string key = calibrationKey("llvmpipe (LLVM 15.0.6, 256 bits)", "4.5 (Core Profile) Mesa 22.3.6");
  EXPECT_EQ(key, calibrationKey("llvmpipe (LLVM 15.0.6, 256 bits)", "4.5 (Core Profile) Mesa 22.3.6"));
  for (char c : key)
    EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_')
        << "'" << c << "' in " << key;
  EXPECT_EQ(key.rfind("llvmpipe__LLVM_15.0.6__256_bits_", 0), 0u) << key;
  std::set<std::string> keys = {key};
  // Another driver version, another renderer, and strings that differ only in replaced bytes
  // (or in which side of the join a byte is on) all get their own key.
  for (const auto& [renderer, version] : std::vector<std::pair<std::string, std::string>>{
           {"llvmpipe (LLVM 15.0.6, 256 bits)", "4.5 (Core Profile) Mesa 23.0.0"},
           {"NVIDIA H200/PCIe/SSE2", "4.6.0 NVIDIA 550.54"},
           {"NVIDIA H200 PCIe SSE2", "4.6.0 NVIDIA 550.54"},
           {"NVIDIA H200/PCIe/SSE2|4.6.0", "NVIDIA 550.54"},
           {"", ""}})
    EXPECT_TRUE(keys.insert(calibrationKey(renderer, version)).second) << renderer << " | " << version;
  EXPECT_LE(calibrationKey(std::string(1000, 'x'), "v").size(), 96u + 17u);
}

TEST(RendererCalibration, CacheDirectoryFollowsXdgThenHome) {
  {
    const ScopedEnv xdg("XDG_CACHE_HOME", "/some/cache");
    EXPECT_EQ(calibrationCacheDirectory(), "/some/cache/penumbra");
  }
  {
    const ScopedEnv xdg("XDG_CACHE_HOME", nullptr), home("HOME", "/home/someone");
    EXPECT_EQ(calibrationCacheDirectory(), "/home/someone/.cache/penumbra");
  }
  {
    const ScopedEnv xdg("XDG_CACHE_HOME", ""), home("HOME", nullptr);
    EXPECT_EQ(calibrationCacheDirectory(), "");
  }
  EXPECT_EQ(calibrationCachePath("/d", "r", "v"), "/d/calibration-" + calibrationKey("r", "v") + ".json");
}

TEST(RendererCalibration, FileRoundTrips) {
  const RendererCalibration written = sample();
  std::string problem;
  const auto read = calibrationFromJson(calibrationToJson(written), problem, &written.renderer,
                                        &written.glVersion);
  ASSERT_TRUE(read) << problem;
  EXPECT_EQ(read->source, "cached");
  EXPECT_EQ(read->renderer, written.renderer);
  EXPECT_EQ(read->glVersion, written.glVersion);
  EXPECT_EQ(read->measuredAt, written.measuredAt);
  EXPECT_EQ(read->texelLevelsPerPixelRay, written.texelLevelsPerPixelRay);
  EXPECT_EQ(read->nbufferTexelLevelsPerEyePixel, written.nbufferTexelLevelsPerEyePixel);
  EXPECT_EQ(read->traceMsPerPixelRay, written.traceMsPerPixelRay);
}

TEST(RendererCalibration, ReaderRejectsBadContentWithAReason) {
  const RendererCalibration good = sample();
  const std::string text = calibrationToJson(good);
  const nlohmann::json json = nlohmann::json::parse(text);
  const auto with = [&](const char* key, const nlohmann::json& value) {
    nlohmann::json changed = json;
    changed[key] = value;
    return changed.dump();
  };
  const auto without = [&](const char* key) {
    nlohmann::json changed = json;
    changed.erase(key);
    return changed.dump();
  };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "not JSON"},
      {"{", "not JSON"},
      {text.substr(0, text.size() / 2), "not JSON"},  // a file cut short
      {"[1, 2]", "not a JSON object"},
      {"\"calibration\"", "not a JSON object"},
      {with("format", "penumbra-settings"), "\"format\""},
      {with("format", 1), "\"format\""},
      {with("version", 2), "\"version\""},
      {with("version", "1"), "\"version\""},
      {without("version"), "\"version\""},
      {without("texel_levels_per_pixel_ray"), "\"texel_levels_per_pixel_ray\" missing"},
      {with("texel_levels_per_pixel_ray", "8"), "\"texel_levels_per_pixel_ray\" missing or not a number"},
      {with("texel_levels_per_pixel_ray", 0), "outside"},
      {with("texel_levels_per_pixel_ray", -3), "outside"},
      {with("nbuffer_texel_levels_per_eye_pixel", 1e9), "outside"},
      {with("nbuffer_texel_levels_per_eye_pixel", nullptr), "not a number"},
      {with("renderer", 5), "\"renderer\""},
      {without("notes"), "\"notes\""},
      {with("renderer", "Another GPU"), "written for renderer"},
      {with("gl_version", "4.6.0 NVIDIA 999"), "written for GL_VERSION"},
  };
  for (const auto& [bad, reason] : cases) {
    std::string problem;
    EXPECT_FALSE(calibrationFromJson(bad, problem, &good.renderer, &good.glVersion)) << bad;
    EXPECT_NE(problem.find(reason), std::string::npos) << "'" << problem << "' for " << bad;
  }
  // Without a renderer to check (a pinned file), another renderer's file is accepted.
  std::string problem;
  EXPECT_TRUE(calibrationFromJson(with("renderer", "Another GPU"), problem)) << problem;
}

TEST(RendererCalibration, RequestFromTheEnvironment) {
  {
    const ScopedEnv mode("PENUMBRA_CALIBRATION", nullptr);
    EXPECT_EQ(calibrationRequest().mode, CalibrationMode::Cached);
    EXPECT_EQ(calibrationRequest("refresh").mode, CalibrationMode::Refresh);
  }
  const ScopedEnv mode("PENUMBRA_CALIBRATION", "fallback");
  EXPECT_EQ(calibrationRequest().mode, CalibrationMode::Fallback);
  EXPECT_EQ(calibrationRequest("cached").mode, CalibrationMode::Cached);  // the override wins
  const CalibrationRequest pinned = calibrationRequest("/pinned/calibration.json");
  EXPECT_EQ(pinned.mode, CalibrationMode::Pinned);
  EXPECT_EQ(pinned.file, "/pinned/calibration.json");
}

// Fallback: nothing measured, nothing read or written, the constants.
TEST(RendererCalibration, FallbackMeasuresNothing) {
  headlessContext();
  const TempDirectory dir("penumbra_calibration_fallback");
  const ScopedEnv xdg("XDG_CACHE_HOME", dir.path().c_str());
  int measured = 0;
  const RendererCalibration c = resolveRendererCalibration(
      {CalibrationMode::Fallback, ""}, [&] { return ++measured, sample(); });
  EXPECT_EQ(measured, 0);
  EXPECT_EQ(c.source, "fallback");
  EXPECT_EQ(c.texelLevelsPerPixelRay, kFallbackTexelLevelsPerPixelRay);
  EXPECT_EQ(c.nbufferTexelLevelsPerEyePixel, kFallbackNBufferTexelLevelsPerEyePixel);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "penumbra"));
}

// Cached: measured once and written; read back after; a bad file measured again and replaced;
// refresh measures even over a good file.
TEST(RendererCalibration, CacheIsWrittenReadAndReplacedWhenBad) {
  headlessContext();
  const TempDirectory dir("penumbra_calibration_cache");
  const ScopedEnv xdg("XDG_CACHE_HOME", dir.path().c_str());
  int measured = 0;
  const CalibrationMeasure measure = [&] { return ++measured, sample(); };
  const RendererCalibration first = resolveRendererCalibration({CalibrationMode::Cached, ""}, measure);
  EXPECT_EQ(measured, 1);
  EXPECT_EQ(first.source, "measured");
  ASSERT_FALSE(first.file.empty());
  EXPECT_EQ(first.file.rfind((dir.path() / "penumbra").string(), 0), 0u) << first.file;
  const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  EXPECT_EQ(first.renderer, renderer);

  const RendererCalibration second = resolveRendererCalibration({CalibrationMode::Cached, ""}, measure);
  EXPECT_EQ(measured, 1);
  EXPECT_EQ(second.source, "cached");
  EXPECT_EQ(second.texelLevelsPerPixelRay, sample().texelLevelsPerPixelRay);
  EXPECT_EQ(second.measuredAt, first.measuredAt);

  for (const std::string& bad : {std::string("{\"format\": \"penumbra-renderer-calibration\""),
                                std::string(""), std::string("garbage")}) {
    std::ofstream(first.file, std::ios::trunc) << bad;
    std::string log;
    const RendererCalibration again = resolveRendererCalibration({CalibrationMode::Cached, ""}, measure, &log);
    EXPECT_EQ(again.source, "measured");
    EXPECT_NE(log.find("rejected"), std::string::npos) << log;
    std::string problem;
    EXPECT_TRUE(calibrationFromJson(readFile(first.file), problem)) << problem;  // rewritten whole
  }
  EXPECT_EQ(measured, 4);
  resolveRendererCalibration({CalibrationMode::Refresh, ""}, measure);
  EXPECT_EQ(measured, 5);
  // Nothing but the cache file is left in the directory (no temporary files).
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path() / "penumbra")) ++files, (void)entry;
  EXPECT_EQ(files, 1);
}

// A measurement that left a crossover unresolved (the constant kept) is used, not cached: the
// next process measures again rather than keeping a loaded moment's answer.
TEST(RendererCalibration, UnresolvedMeasurementIsNotCached) {
  headlessContext();
  const TempDirectory dir("penumbra_calibration_unresolved");
  const ScopedEnv xdg("XDG_CACHE_HOME", dir.path().c_str());
  int measured = 0;
  const CalibrationMeasure measure = [&] {
    RendererCalibration c = sample();
    c.nbufferTexelLevelsPerEyePixel = kFallbackNBufferTexelLevelsPerEyePixel;
    c.notes = "N-buffer crossover not resolved";
    return ++measured, c;
  };
  std::string log;
  const RendererCalibration c = resolveRendererCalibration({CalibrationMode::Cached, ""}, measure, &log);
  EXPECT_EQ(c.source, "measured");
  EXPECT_TRUE(c.file.empty());
  EXPECT_NE(log.find("not cached"), std::string::npos) << log;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "penumbra" /
                                       ("calibration-" + calibrationKey(c.renderer, c.glVersion) + ".json")));
  resolveRendererCalibration({CalibrationMode::Cached, ""}, measure);
  EXPECT_EQ(measured, 2);
}

TEST(RendererCalibration, PinnedFileIsUsedAsIsOrRefused) {
  headlessContext();
  const TempDirectory dir("penumbra_calibration_pinned");
  RendererCalibration other = sample();
  other.renderer = "a renderer this machine does not have";
  const std::string path = dir.write("pinned.json", calibrationToJson(other));
  int measured = 0;
  const CalibrationMeasure measure = [&] { return ++measured, sample(); };
  const RendererCalibration pinned = resolveRendererCalibration({CalibrationMode::Pinned, path}, measure);
  EXPECT_EQ(pinned.source, "pinned");
  EXPECT_EQ(pinned.file, path);
  EXPECT_EQ(pinned.nbufferTexelLevelsPerEyePixel, other.nbufferTexelLevelsPerEyePixel);
  const std::string bad = dir.write("bad.json", "{\"format\": 3}");
  EXPECT_THROW(resolveRendererCalibration({CalibrationMode::Pinned, bad}, measure), std::invalid_argument);
  EXPECT_THROW(resolveRendererCalibration({CalibrationMode::Pinned, (dir.path() / "none.json").string()}, measure),
               std::invalid_argument);
  EXPECT_EQ(measured, 0);
}

// The active calibration is what `auto` weighs with: the trace's hierarchy follows the
// crossover (the same scene and view with a tiny and a huge one), and a pipeline run with no
// calibration set uses the constants.
TEST(RendererCalibration, AutoHierarchyFollowsTheActiveCrossover) {
  headlessContext();
  EXPECT_EQ(activeRendererCalibration().source, "fallback");
  const auto hierarchyRan = [](double crossover) {
    RendererCalibration c;
    c.source = "pinned";
    c.nbufferTexelLevelsPerEyePixel = crossover;
    setActiveRendererCalibration(c);
    PipelineRun run(makeBuiltinScene("spheres"), {"light.resolution=512"}, 128, 96);
    run.pipeline->run(*run.frame, {"trace.visibility"});
    return std::make_pair(run.pipeline->lastTime("minmax").ran, run.pipeline->lastTime("nbuffer").ran);
  };
  EXPECT_EQ(hierarchyRan(kMinCrossover), std::make_pair(true, false));
  EXPECT_EQ(hierarchyRan(kMaxCrossover), std::make_pair(false, true));
  setActiveRendererCalibration(RendererCalibration{});
}

// The command line: run.json says which calibration was used; a bad pinned file is bad input.
TEST(RendererCalibration, RunJsonNamesTheCalibrationAndBadPinsExit2) {
  const TempDirectory dir("penumbra_calibration_cli");
  const std::string out = (dir.path() / "out").string();
  {
    const ScopedEnv mode("PENUMBRA_CALIBRATION", "fallback");
    const auto result = runPenumbra("export --scene cube --width 64 --height 48 --out " + out);
    ASSERT_EQ(result.exitCode, 0) << result.output;
    std::ifstream in(dir.path() / "out" / "run.json");
    const nlohmann::json calibration = nlohmann::json::parse(in)["calibration"];
    EXPECT_EQ(calibration["source"], "fallback");
    EXPECT_EQ(calibration["texel_levels_per_pixel_ray"], kFallbackTexelLevelsPerPixelRay);
  }
  RendererCalibration pinned = sample();
  const std::string path = dir.write("pinned.json", calibrationToJson(pinned));
  {
    const ScopedEnv mode("PENUMBRA_CALIBRATION", path.c_str());
    const auto result = runPenumbra("export --scene cube --width 64 --height 48 --out " + out + "2");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    std::ifstream in(dir.path() / "out2" / "run.json");
    const nlohmann::json calibration = nlohmann::json::parse(in)["calibration"];
    EXPECT_EQ(calibration["source"], "pinned");
    EXPECT_EQ(calibration["nbuffer_texel_levels_per_eye_pixel"], pinned.nbufferTexelLevelsPerEyePixel);
  }
  const std::string bad = dir.write("bad.json", "{}");
  const ScopedEnv mode("PENUMBRA_CALIBRATION", bad.c_str());
  const auto result = runPenumbra("export --scene cube --width 64 --height 48 --out " + out + "3");
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("not a calibration file"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out3"));
}

// The real measurement, once: `penumbra calibrate --refresh` measures; a second
// `penumbra calibrate` reads the cache. Only what holds on any load is asserted: either the
// file is written (accepted by the reader, named by its key, read back as `cached`), or, when
// the machine's load left a crossover unresolved, the command says it was not cached, no
// file exists and the next command measures again.
TEST(RendererCalibration, CalibrateCommandMeasuresThenReadsTheCache) {
  const TempDirectory dir("penumbra_calibration_measure");
  const ScopedEnv xdg("XDG_CACHE_HOME", dir.path().c_str()), mode("PENUMBRA_CALIBRATION", nullptr);
  const auto measured = runPenumbra("calibrate --refresh");
  ASSERT_EQ(measured.exitCode, 0) << measured.output;
  EXPECT_NE(measured.output.find("measured on "), std::string::npos) << measured.output;
  std::vector<std::filesystem::path> files;
  if (std::filesystem::exists(dir.path() / "penumbra"))
    for (const auto& entry : std::filesystem::directory_iterator(dir.path() / "penumbra")) files.push_back(entry.path());
  const auto again = runPenumbra("calibrate");
  ASSERT_EQ(again.exitCode, 0) << again.output;
  if (measured.output.find("not cached") != std::string::npos) {
    EXPECT_NE(measured.output.find("not resolved"), std::string::npos) << measured.output;
    EXPECT_TRUE(files.empty());
    EXPECT_NE(again.output.find("measured on "), std::string::npos) << again.output;
    return;
  }
  ASSERT_EQ(files.size(), 1u) << measured.output;
  std::string problem;
  const auto read = calibrationFromJson(readFile(files[0].string()), problem);
  ASSERT_TRUE(read) << problem;
  EXPECT_EQ(files[0].filename().string(),
            "calibration-" + calibrationKey(read->renderer, read->glVersion) + ".json");
  EXPECT_NE(again.output.find("cached on "), std::string::npos) << again.output;
}

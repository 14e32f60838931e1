#include "export/frame_export.h"

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "base/input_error.h"
#include "core/progress.h"
#include "figures/categories.h"
#include "gl/renderer_calibration.h"
#include "io/colormap.h"
#include "io/headless_session.h"
#include "io/image_export.h"
#include "io/output_path.h"

namespace {

// The PNG of one output layer again, with its annotation band.
void writeAnnotatedPng(const std::filesystem::path& png, const Frame& frame, const std::string& key,
                       const GlTexture& texture, const Output& output, int layer,
                       const std::string& keyParameters) {
  const std::vector<float> values = texture.readFloats(layer);
  DisplayHint hint = output.display;
  const bool automatic = applyDataRange(hint, values, texture.channelCount());  // io/colormap.h
  Annotation annotation;
  annotation.caption = frame.scene.name + " · " + key +
                       (texture.isArray() ? " level " + std::to_string(layer) : "") + " · " +
                       std::to_string(texture.width()) + "x" + std::to_string(texture.height()) +
                       (keyParameters.empty() ? "" : " · " + keyParameters);
  const int channel = hint.channel < texture.channelCount() ? hint.channel : -1;
  if (channel >= 0 && hint.colormap == Colormap::Categorical)
    annotation.legend = categoryLegend(values, texture.channelCount(), channel, output.doc);
  else if (channel >= 0)
    annotation.bar = ColorBar{hint.colormap, hint.black, hint.white,
                              key + ": " + output.channels.at(size_t(channel)) +
                                  (automatic ? " · auto range (p99)" : "")};
  const AnnotatedImage annotated = annotateView(  // small outputs enlarged first (annotate.h)
      displayRgb8(values, texture.width(), texture.height(), texture.channelCount(), hint),
      texture.width(), texture.height(), annotation);
  writePng(png, annotated.rgb, annotated.width, annotated.height);
}

}  // namespace

std::vector<std::string> exportFrame(const std::string& target, const Frame& frame,
                                     const Pipeline& pipeline, const std::string& renderer,
                                     bool annotate, const std::string& keyParameters) {
  // The output rule (io/output_path.h): a directory that is not an earlier export is
  // refused before anything is written (the window's "Export all" and a script's
  // export_all come here without the command line's check). One transaction: every file
  // goes into a temporary directory, run.json (the manifest) last, renamed into place.
  checkOutputDirectory(target, "export", "run.json");
  DirectoryTransaction transaction(target, "run.json");
  const std::filesystem::path directory = transaction.path();
  std::vector<std::string> written;
  nlohmann::json run;
  run["scene"] = frame.scene.name;
  run["time"] = frame.scene.time;  // seconds: the pose of an animated scene
  run["triangles"] = frame.scene.triangleCount();
  const Bounds bounds = frame.scene.bounds(false);
  run["bounds"] = {{"min", {bounds.min.x, bounds.min.y, bounds.min.z}},
                   {"max", {bounds.max.x, bounds.max.y, bounds.max.z}}};
  if (!frame.scene.notes.empty()) run["scene_notes"] = frame.scene.notes;
  run["renderer"] = renderer;
  run["eye_size"] = {frame.eyeWidth, frame.eyeHeight};
  run["frame_key"] = frame.frameKey;
  run["light_frame"] = {{"light_depth", frame.light.lightDepth},
                        {"z_near", frame.light.zNear},
                        {"z_far", frame.light.zFar}};
  // Progress (core/progress.h): one step per output written; a bar when it takes a second.
  int files = 0;
  for (const auto& stage : pipeline.stages())
    for (const Output& output : stage->outputs())
      if (frame.has(stage->name() + "." + output.name)) ++files;
  ProgressTask progress("export", files);
  for (const auto& stage : pipeline.stages()) {
    nlohmann::json params = nlohmann::json::object();
    for (const Param& param : stage->params()) params[param.key] = param.toString();
    run["parameters"][stage->name()] = params;
    for (const Output& output : stage->outputs()) {
      const std::string key = stage->name() + "." + output.name;
      if (!frame.has(key)) continue;
      const GlTexture& texture = frame.texture(key);
      run["outputs"][key] = {{"size", {texture.width(), texture.height()}},
                             {"layers", std::max(texture.layers(), 1)},
                             {"mip_levels", texture.levels()},
                             {"channels", output.channels}};
      for (int layer = 0; layer < std::max(texture.layers(), 1); ++layer) {
        // A mipmapped output (the min-max mipmap): one file per mip level, "KEY.M<m>", each
        // at its own size (a view of that level, gl_texture.h).
        for (int mip = 0; mip < texture.levels(); ++mip) {
          const GlTexture levelView =
              texture.levels() > 1 ? GlTexture::levelView(texture, mip) : GlTexture();
          const GlTexture& shown = texture.levels() > 1 ? levelView : texture;
          const std::string stem = texture.isArray()        ? key + ".L" + std::to_string(layer)
                                   : texture.levels() > 1 ? key + ".M" + std::to_string(mip)
                                                          : key;
          for (const auto& path : exportTexture(directory, stem, shown, output, layer))
            written.push_back((transaction.target() / path.filename()).string());
          if (annotate)
            writeAnnotatedPng(directory / (stem + ".png"), frame, key, shown, output, layer,
                              keyParameters);
        }
      }
      progress.advance(key);
    }
  }
  for (const StageTime& time : pipeline.lastTimes())
    run["stage_milliseconds"][time.stage] = time.milliseconds;
  for (const auto& [name, value] : frame.counters) run["counters"][name] = value;
  // What the parameters left at `auto` chose this frame, and why (the inspector's list).
  run["auto_choices"] = frame.autoReasons;
  // The crossovers `auto` weighed costs with (gl/renderer_calibration.h).
  const RendererCalibration calibration = activeRendererCalibration();
  run["calibration"] = {{"source", calibration.source},
                        {"file", calibration.file},
                        {"measured_at", calibration.measuredAt},
                        {"texel_levels_per_pixel_ray", calibration.texelLevelsPerPixelRay},
                        {"nbuffer_texel_levels_per_eye_pixel", calibration.nbufferTexelLevelsPerEyePixel},
                        {"describe", calibration.describe()}};
  writeTextFile(directory / "run.json", run.dump(2) + "\n");
  written.push_back((transaction.target() / "run.json").string());
  transaction.commit();
  return written;
}

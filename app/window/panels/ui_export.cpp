#include "window/panels/ui_export.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include "export/frame_export.h"
#include "figures/annotate.h"
#include "io/image_export.h"
#include "window/panels/ui_export_annotation.h"
#include "window/ui_state.h"

namespace fs = std::filesystem;

namespace {

// After a failed run the frame holds a mix of new, blank and stale outputs.
std::string refusal(const UiState& state) {
  return "export refused: the last pipeline run failed (" + state.session.runError +
         "); its outputs are incomplete. Fix the settings (or the shader) until a run succeeds.";
}

std::string sanitized(std::string text) {
  for (char& c : text)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '-';
  return text;
}

// The rows of `crop` (image rows, top first) out of GL-ordered values (bottom row first).
std::vector<float> cropped(const std::vector<float>& values, int width, int height, int channels,
                           const ImageRect& crop) {
  std::vector<float> out;
  out.reserve(size_t(crop.width) * crop.height * channels);
  for (int glRow = height - crop.y - crop.height; glRow < height - crop.y; ++glRow) {
    const auto rowStart = values.begin() + (long(glRow) * width + crop.x) * channels;
    out.insert(out.end(), rowStart, rowStart + long(crop.width) * channels);
  }
  return out;
}

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

// 1. Scene, output, level, eye size, then the producing stage's changed parameters.
std::string exportStem(const UiState& state, const std::string& stageDotOutput, int layer) {
  std::string stem = state.session.scene.name + "_" + stageDotOutput;
  if (state.session.frame && state.session.frame->has(stageDotOutput)) {
    const GlTexture& texture = state.session.frame->texture(stageDotOutput);
    if (texture.isArray()) stem += "_L" + std::to_string(layer);
    else if (texture.levels() > 1) stem += "_M" + std::to_string(layer);  // the mip level
  }
  if (state.session.frame) {
    char size[40];
    std::snprintf(size, sizeof size, "_%dx%d", state.session.frame->eyeWidth, state.session.frame->eyeHeight);
    stem += size;
  }
  const std::string stageName = stageDotOutput.substr(0, stageDotOutput.find('.'));
  for (const auto& stage : state.session.pipeline.stages()) {
    if (stage->name() != stageName) continue;
    for (const Param& param : stage->params()) {
      auto declared = state.session.parameterDefaults.find(stageName + "." + param.key);
      if (declared != state.session.parameterDefaults.end() && declared->second == param.value) continue;
      stem += "_" + param.key + "-" + param.toString();
    }
  }
  return sanitized(stem);
}

// 2. One view: the texture's current level, raw or through the view's own mapping.
std::string exportViewFiles(const UiState& state, const ViewPanel& view, const std::string& target,
                            ExportKind kind, bool annotate, const ImageRect& crop) {
  if (!state.session.runError.empty()) return refusal(state);
  std::string problem;
  const GlTexture* shown = shownTexture(state, view, &problem);
  if (!state.session.outputOf(view.output) || !shown)
    return "export: " + (problem.empty() ? "'" + view.output + "' has not been written this frame" : problem);
  try {
    const GlTexture& texture = *shown;
    const int layer = texture.isArray() ? std::clamp(view.settings.layer, 0, texture.layers() - 1) : 0;
    fs::path png, exr;
    if (endsWith(target, ".png")) png = target;
    else if (endsWith(target, ".exr")) exr = target;
    else {
      const fs::path directory = target.empty() ? fs::path(kDefaultExportDirectory) : fs::path(target);
      const GlTexture& source = state.session.frame->texture(view.output);  // a difference is 2D
      const int sourceLayer = std::clamp(view.settings.layer, 0,
                                         std::max(source.isArray() ? source.layers() : source.levels(), 1) - 1);
      std::string stem = exportStem(state, view.output, sourceLayer);
      if (!view.minus.empty())  // "cube_light_layers.far-minus-light_layers.near_..."
        stem.insert(state.session.scene.name.size() + 1 + view.output.size(),
                    "-minus-" + view.minus + (view.clipNegative ? "-clipped" : ""));
      if (kind != ExportKind::Exr) png = directory / (stem + ".png");
      if (kind != ExportKind::Png) exr = directory / (stem + ".exr");
    }
    std::vector<float> values = texture.readFloats(layer);
    int width = texture.width(), height = texture.height();
    if (!crop.empty()) {
      if (crop.x < 0 || crop.y < 0 || crop.x + crop.width > width || crop.y + crop.height > height)
        return "export: the crop [" + std::to_string(crop.x) + ", " + std::to_string(crop.y) + ", " +
               std::to_string(crop.width) + ", " + std::to_string(crop.height) + "] reaches past the " +
               std::to_string(width) + "x" + std::to_string(height) + " image";
      values = cropped(values, width, height, texture.channelCount(), crop);
      width = crop.width;
      height = crop.height;
    }
    std::string written;
    for (const fs::path& path : {png, exr}) {
      if (path.empty()) continue;
      if (path.has_parent_path()) fs::create_directories(path.parent_path());
      if (path == png) {
        std::vector<std::uint8_t> rgb = displayRgb8ForView(values, width, height,
                                                           texture.channelCount(), view.settings);
        int pngWidth = width, pngHeight = height;
        if (annotate) {  // small outputs enlarged first so the labels fit (annotate.h)
          AnnotatedImage annotated = annotateView(
              rgb, width, height, viewAnnotation(state, view, values, texture.channelCount()));
          rgb = std::move(annotated.rgb);
          pngWidth = annotated.width, pngHeight = annotated.height;
        }
        writePng(png, rgb, pngWidth, pngHeight);
      } else
        writeExr(exr, values, width, height, shownChannelNames(state, view));
      written += (written.empty() ? "" : ", ") + fs::absolute(path).string();
    }
    return "wrote " + written;
  } catch (const std::exception& error) {
    return std::string("export failed: ") + error.what();
  }
}

// 3. Everything, through the same function as `penumbra export`.
std::string exportAllStages(UiState& state, const std::string& directory) {
  if (!state.session.frame) return "export: no frame yet";
  // The window runs only what it shows: every output first (the next shown run drops them).
  if (!state.session.runAll().empty()) return refusal(state);
  fs::path target = directory;
  if (target.empty())
    target = fs::path(kDefaultExportDirectory) /
             sanitized(state.session.scene.name + "_all_" + std::to_string(state.session.frame->eyeWidth) + "x" +
                       std::to_string(state.session.frame->eyeHeight));
  try {
    const auto written = exportFrame(target.string(), *state.session.frame, state.session.pipeline, state.session.renderer);
    return "wrote " + std::to_string(written.size()) + " files into " + fs::absolute(target).string();
  } catch (const std::exception& error) {
    return std::string("export failed: ") + error.what();
  }
}

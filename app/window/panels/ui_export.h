// Exports from the window (docs/design.md#exports): a view "as displayed" (PNG, the view's current
// channels, range, colormap and overlay) or raw (EXR), and "export all stages", which writes
// exactly what `penumbra export` writes for the same settings (app/export/frame_export.h).
// File names say the scene, the output, the eye size and the stage's non-default parameters.
#pragma once
#include <map>
#include <string>

class UiState;
struct ViewPanel;

enum class ExportKind { Png, Exr, Both };

// A rectangle of an image in image coordinates (row 0 at the top); empty = the whole image.
struct ImageRect {
  int x = 0, y = 0, width = 0, height = 0;
  bool empty() const { return width <= 0 || height <= 0; }
};

// "cube_hard_shadow.visibility_640x480_bias-0.01" (array textures: "..._L3" for the level).
std::string exportStem(const UiState& state, const std::string& stageDotOutput, int layer);

// `target`: "" -> the default directory with a generated name; "x.png" / "x.exr" -> exactly
// that file (kind from the extension); anything else -> a directory, generated names.
// `annotate`: the PNG carries a colour bar or legend and a caption below the image
// (ui_export_annotation.h); the EXR stays raw. `crop`: both files hold only that rectangle
// (a lesson's zoom on a detail); one reaching past the image is refused. Returns the status
// line: the absolute paths written, or what went wrong.
std::string exportViewFiles(const UiState& state, const ViewPanel& view,
                            const std::string& target, ExportKind kind, bool annotate = false,
                            const ImageRect& crop = {});
// Every output + run.json into `directory` ("" -> default directory / "<scene>_all_<WxH>").
std::string exportAllStages(UiState& state, const std::string& directory);

// Where "" exports go (relative to the working directory).
constexpr const char* kDefaultExportDirectory = "penumbra_exports";

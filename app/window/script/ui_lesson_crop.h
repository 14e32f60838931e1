// A lesson's crop (thesis Fig 3.5; docs/lessons.md): {"crop": [x, y, w, h]} in image coordinates
// (row 0 at the top) makes the following export_view panels hold only that rectangle, and
// {crop.rmse}, {crop.meanSigned}, ... in a text the error stage's numbers over the pixels
// that count inside it; {"crop": "none"} goes back to the whole image. A local effect (one
// horn's self-shadow) can then be shown and measured where it is, not drowned in a
// whole-image RMSE.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "window/panels/ui_export.h"

class UiState;

// [x, y, w, h] with x, y >= 0 and w, h > 0, or "none". "" or what was expected.
std::string checkCrop(const nlohmann::json& value);
ImageRect cropFromJson(const nlohmann::json& value);  // "none" -> an empty rectangle

// Whether `name` is a crop number (crop.rmse, crop.max, crop.meanAbsInShadow, crop.p99,
// crop.meanSigned, crop.pixels, crop.pixelsInShadow).
bool isCropNumber(const std::string& name);
// That number for the current frame: the error stage's metrics (reference/error_metrics.h)
// over its counted pixels inside `crop`. False, with `problem`, when there is no crop, the
// crop leaves the eye image, or the error stage has nothing to compare this frame.
bool cropNumber(const UiState& state, const ImageRect& crop, const std::string& name,
                double& value, std::string& problem);

// The view state in the settings JSON (app/window/script/ui_settings.h): the UI scale, the
// layout, which view is active, whether zoom and pan are linked, the right panel's tab, and
// for each shown view its output (and what it subtracts), lock, array level, zoom and centre,
// colormap, channels, black / white and overlay.
//
//   "ui_scale": 1.5,
//   "views": {"layout": "grid", "active": 0, "linked": true, "side_panel": "speed_error",
//             "panels": [{"output": "composite.color", "minus": "", "clip_negative": false,
//                         "locked": false, "level": 0, "zoom": "fit" | 2.5,
//                         "center": [x, y], "texture": [w, h], "colormap": "gray",
//                         "channels": "RGB", "range": [0, 1], "overlay": false}, ...]}
//
// `center` is in texel units of a texture `texture` in size; a view showing another size
// keeps the same relative place (as after a resize).
#pragma once
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

class UiState;

nlohmann::json uiScaleJson(const UiState& state);
nlohmann::json viewsJson(const UiState& state);
// Checks `value` (at JSON pointer `pointer`) completely; returns what applies it, or throws
// the first problem as std::invalid_argument("pointer: what is valid").
std::function<void(UiState&)> readUiScale(const UiState& state, const nlohmann::json& value,
                                          const std::string& pointer);
std::function<void(UiState&)> readViews(const UiState& state, const nlohmann::json& value,
                                        const std::string& pointer);

// The window's settings as JSON (save / load, `penumbra --config FILE`): scene, eye size,
// camera, light, every parameter as "stage.key": value, the UI scale and the views
// (app/window/script/ui_settings_views.h). Loading is all or nothing: a bad
// file changes nothing and the message names the JSON path and what is valid.
//
//   {"penumbra_settings": 1, "scene": "cube", "eye": "fit" | [640, 480],
//    "camera": {"position": [x,y,z], "target": [..], "up": [..], "fov_y_degrees": 45},
//    "light": {"center": [..], "forward": [..], "up": [..], "width": 1.6, "height": 1.6},
//    "parameters": {"hard_shadow.offset": 0.005, "composite.shadow": "hard_shadow", ...},
//    "ui_scale": 1, "views": {"layout": "one", "panels": [{"output": ..., "zoom": ...}], ...}}
#pragma once
#include <nlohmann/json.hpp>
#include <string>

class UiState;

// 1. The current state as JSON (parameter values exactly, as numbers, booleans, strings).
nlohmann::json settingsJson(const UiState& state);
// 2. Checks everything first, then applies (loading the scene if it differs). "" or error.
std::string applySettingsJson(UiState& state, const nlohmann::json& settings);
// 3. Files; both return the status line ("saved ..."/"loaded ...") or the error.
std::string saveSettingsFile(const UiState& state, const std::string& path);
std::string loadSettingsFile(UiState& state, const std::string& path, bool& ok);

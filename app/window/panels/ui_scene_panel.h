// The top of the left panel: scene picker (built-ins or a path), eye image size, camera and
// light sliders, how the pipeline re-runs, settings save/load, shader reload, export all.
#pragma once

class UiState;

void drawScenePanel(UiState& state);

// The left panel: the stages in execution order (thesis Algorithm 1), each with its summary,
// thesis section, median time, outputs (click: show in the active view; Ctrl+click: in the
// second view) and parameters, all drawn from the stages' declarations.
#pragma once

class UiState;

void drawPipelinePanel(UiState& state);

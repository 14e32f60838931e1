// The right panel: the picked texel's raw values in every output of the same size (every
// level of array outputs), per-stage timings as bars (median of recent runs), the frame's
// counters, and the per-ray march trace of the picked pixel (ui_trace_panel.h hook).
#pragma once

class UiState;

void drawInspector(UiState& state);

// The "Temporal" tab of the side panel (docs/decisions/120-temporal-stability.md): a time plot
// of the last frames' temporal change of every shadow method the views show, while the
// timeline plays (or, with a new frame key per run, on a static scene): per run, the mean
// |visibility - visibility of the run before| over the pixels counted in both runs whose
// ground truth did not change (app/stats/temporal.h). The ground truth is the one the
// comparison is set against (error.against) when it ran this run and the run before; without
// it every counted pixel counts as stable and the panel says so.
#pragma once

class UiState;

// After each window frame's run: records a new point when the pipeline ran (called every
// frame, whether the tab is shown or not); with "new key every run" on, moves the frame key.
void stepTemporalPanel(UiState& state);
// The tab's contents, drawn into the current window.
void drawTemporalPanel(UiState& state);

// A run refused as too long (a stage's cost estimate over its budget parameter, core/
// run_control.h) asks before anything more happens: "Run anyway" raises that budget just
// enough for this run (a longer one asks again), "Cancel" keeps the settings and the last
// image. While a run is under way, Esc cancels it (between stages, SSM tiles, reference tiles);
// a run that has lasted a second shows a "running" overlay over the last frame, with what it
// is doing and a Cancel button that does the same (drawn from the run's own checks, so it is
// live exactly when a cancel can take effect).
#pragma once

struct UiState;

void drawRunBudgetModal(UiState& state);
// Installs the poll that lets Esc (or closing the window) cancel a run in progress.
struct GLFWwindow;
void installRunCancelKeys(GLFWwindow* window);
// Whether the overlay covered the screen since the last call: the next frame must be drawn.
bool takeRunOverlayDrawn();

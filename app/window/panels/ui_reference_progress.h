// The live error in the window (issues 5 and 10): a "compare with ground truth" button putting
// the comparison's first output (window/ui_graph.h comparisonOutput: error.signed) beside the
// method, the ground truth in use and why (window/ui_live_truth.h: raster4d when interactive,
// else Embree; the user's choice kept), and, while Embree traces in the background, a
// progress bar with a Cancel button (app/reference/reference_trace.h referenceStageProgress()).
#pragma once
#include <string>

class UiState;

// Chooses the ground truth (the automatic rule, unless the user chose), enables it
// ("<stage>.enabled") and shows the comparison in view B; "" or the problem.
std::string compareWithReference(UiState& state);
// Drawn under the comparison stage (error) in the pipeline panel.
void drawReferenceProgress(UiState& state);

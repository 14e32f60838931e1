// The ground-truth stage's progress in the window (issue 5): a progress bar with a Cancel
// button while the background trace runs (app/reference/reference_trace.h
// referenceStageProgress()), and a "compare with reference" button putting the comparison's
// first output (window/ui_graph.h comparisonOutput: error.signed) beside the method.
#pragma once
#include <string>

class UiState;

// Enables the ground truth ("<stage>.enabled") and shows the comparison in view B; "" or
// the problem.
std::string compareWithReference(UiState& state);
// Drawn under the ground-truth stage in the pipeline panel.
void drawReferenceProgress(UiState& state);

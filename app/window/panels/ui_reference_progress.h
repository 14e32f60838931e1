// The reference stage's progress in the window (issue 5): a progress bar with a Cancel
// button while the background trace runs (app/reference/reference_trace.h referenceStageProgress()),
// and a "compare with reference" button putting error.signed beside the method.
#pragma once
#include <string>

class UiState;

// Enables the reference and shows error.signed in view B; "" or the problem.
std::string compareWithReference(UiState& state);
// Drawn under the reference stage in the pipeline panel.
void drawReferenceProgress(UiState& state);

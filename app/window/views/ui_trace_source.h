// Connects the per-ray trace panel (ui_trace_panel.h) to the stage that records one pixel's
// rays (window/ui_graph.h recordingStage: the trace). The window asks it to record the picked
// eye pixel and the panel reads the recorded steps (stages/monte_carlo/trace/trace_steps.h) (shaders/shared/trace_layout.h), its
// visibility and the layers wired to its "near" / "far" slots. Without such a stage these
// functions do nothing.
#pragma once

class UiState;
struct ViewState;

// Installs the views' traceSource that converts the recorded steps (stages/monte_carlo/trace/trace_steps.h) of one ray.
void installFrameTraceSource(ViewState& views);
// Points the recording at the pick when the pick is an eye pixel (re-runs the pipeline).
void recordPickedPixel(UiState& state);

// Connects the per-ray trace panel (ui_trace_panel.h) to the trace stage: the window asks
// the stage to record the picked eye pixel (parameters trace.record_x / trace.record_y, in
// image coordinates) and the panel reads Frame::traceSteps (shaders/shared/trace_layout.h).
// Without a trace stage (no such parameters) both functions do nothing.
#pragma once

class UiState;

// Installs the rayTraceSource() that converts Frame::traceSteps of one ray.
void installFrameTraceSource();
// Points the recording at the pick when the pick is an eye pixel (re-runs the pipeline).
void recordPickedPixel(UiState& state);

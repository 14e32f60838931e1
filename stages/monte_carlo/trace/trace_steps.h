// The trace's recorded steps (trace.record_x / record_y): every step of every ray of one
// pixel, as the shaders write them (shaders/shared/trace_layout.h). The trace reads them back
// after the run into the frame's read-back bytes under "trace.steps"; readers (the window's
// ray trace panel, `penumbra trace`, tests) take them from here.
#pragma once
#include <cstring>
#include <vector>

#include "core/frame.h"
#include "gl/gpu_layout_trace.h"

inline constexpr const char* kTraceStepsKey = "trace.steps";

// The steps recorded in `frame`'s last run of the trace (none: not recording, or not run).
inline std::vector<gpu::TraceStep> recordedTraceSteps(const Frame& frame) {
  std::vector<gpu::TraceStep> steps;
  const auto bytes = frame.readBack.find(kTraceStepsKey);
  if (bytes == frame.readBack.end()) return steps;
  steps.resize(bytes->second.size() / sizeof(gpu::TraceStep));
  if (!steps.empty()) std::memcpy(steps.data(), bytes->second.data(), steps.size() * sizeof(gpu::TraceStep));
  return steps;
}

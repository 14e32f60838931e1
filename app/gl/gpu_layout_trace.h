// The trace stage's blocks (shaders/shared/trace_layout.h) seen from C++, and checked.
#pragma once
#include "gl/gpu_layout.h"

namespace gpu {
#include "shared/trace_layout.h"
}  // namespace gpu

static_assert(offsetof(gpu::TraceParams, config) == 0);
static_assert(offsetof(gpu::TraceParams, switches) == 16);
static_assert(offsetof(gpu::TraceParams, limits) == 32);
static_assert(offsetof(gpu::TraceParams, stepping) == 48);
static_assert(offsetof(gpu::TraceParams, record) == 64);
static_assert(offsetof(gpu::TraceParams, eye) == 80);
static_assert(sizeof(gpu::TraceParams) == 96);
// std430 array stride of TraceStep: 4 x 16 bytes, no padding.
static_assert(offsetof(gpu::TraceStep, window) == 16);
static_assert(offsetof(gpu::TraceStep, depths) == 32);
static_assert(offsetof(gpu::TraceStep, stepping) == 48);
static_assert(sizeof(gpu::TraceStep) == 64);

namespace binding {
constexpr unsigned kTraceParams = 1;   // uniform
constexpr unsigned kTraceRecords = 0;  // storage: uvec4 header (x = count), TraceStep[]
constexpr unsigned kTraceTotals = 1;   // storage: uint[TOTAL_COUNT]
}  // namespace binding

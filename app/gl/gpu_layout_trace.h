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

static_assert(gpu::distinctBelow({TRACE_WS_POSITION_UNIT, TRACE_WS_NORMAL_UNIT, TRACE_NEAR_UNIT,
                                  TRACE_FAR_UNIT, TRACE_LEVELS_UNIT, TRACE_MINMAX_UNIT,
                                  TRACE_MASK_UNIT, TRACE_ZRANGE_UNIT},
                                 gpu::kTextureUnits));
static_assert(gpu::distinctBelow({TRACE_VISIBILITY_IMAGE, TRACE_COST_IMAGE}, gpu::kImageUnits));
static_assert(gpu::distinctBelow({FRAME_BLOCK_BINDING, LIGHT_BLOCK_BINDING, TRACE_PARAMS_BINDING},
                                 gpu::kUniformBindings));
static_assert(gpu::distinctBelow({TRACE_RECORDS_BINDING, TRACE_TOTALS_BINDING,
                                  TRACE_PARTIALS_BINDING, 3 /* list */},
                                 gpu::kStorageBindings));
static_assert(TRACE_PIXELS_LOCATION != 0 /* ROW_OFFSET_LOCATION */);

namespace binding {
constexpr unsigned kTraceParams = TRACE_PARAMS_BINDING;
constexpr unsigned kTraceRecords = TRACE_RECORDS_BINDING;
constexpr unsigned kTraceTotals = TRACE_TOTALS_BINDING;
}  // namespace binding

// Soft-shadow-map blocks (shaders/shared/ssm_*.h) seen from C++, checked.
#pragma once
#include "gl/gpu_layout.h"

namespace gpu {
#include "shared/ssm_layout.h"
#include "shared/ssm_query_layout.h"
}  // namespace gpu

static_assert(offsetof(gpu::SsmParams, pick) == 16 && offsetof(gpu::SsmParams, tolerance) == 32 &&
              sizeof(gpu::SsmParams) == 48);
static_assert(sizeof(gpu::DepthBounds) == 16 && sizeof(gpu::SsmCounters) == 16 &&
              sizeof(gpu::SsmWork) == 16);
static_assert(offsetof(gpu::SsmPatchQuery, depths) == 16 && sizeof(gpu::SsmPatchQuery) == 48);
static_assert(offsetof(gpu::SsmPatchResult, extent) == 16 && sizeof(gpu::SsmPatchResult) == 32);

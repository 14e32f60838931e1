// Test-only ray query blocks (shaders/shared/ray_query_layout.h) seen from C++, checked.
#pragma once
#include "gl/gpu_layout.h"

namespace gpu {
#include "shared/ray_query_layout.h"
}  // namespace gpu

static_assert(offsetof(gpu::RayQuery, depths) == 16 && sizeof(gpu::RayQuery) == 32);
static_assert(sizeof(gpu::RayQueryResult) == 16);

// PCSS block (stages/baselines/pcss/pcss_layout.h) seen from C++, checked.
#pragma once
#include "gl/gpu_layout.h"

namespace gpu {
#include "baselines/pcss/pcss_layout.h"
}  // namespace gpu

static_assert(sizeof(gpu::PcssParams) == 16);

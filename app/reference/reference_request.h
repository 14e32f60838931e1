// The reference's request for one frame: the G-buffer's receivers read back, the light as
// the trace samples it, and the origin offset (app/reference/reference_trace.h). Shared by the stage
// `reference` and `penumbra bench` (which times a sample of it before committing).
#pragma once
#include "core/frame.h"
#include "reference/reference_trace.h"

// Needs gbuffer.wsPosition and gbuffer.wsNormal written in `frame`.
ReferenceRequest makeReferenceRequest(const Frame& frame, int samplesPerSide, bool stratified);

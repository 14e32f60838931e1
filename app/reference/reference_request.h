// The reference's request for one frame: the G-buffer's receivers read back, the light as
// the trace samples it, and the origin offset (app/reference/reference_trace.h). Shared by the stage
// `reference` and `penumbra bench` (which times a sample of it before committing).
#pragma once
#include "core/frame.h"
#include "reference/reference_trace.h"

// The receivers are the G-buffer's world positions and normals; the light is frame.light.
ReferenceRequest makeReferenceRequest(const Frame& frame, const GlTexture& wsPosition,
                                      const GlTexture& wsNormal, int samplesPerSide,
                                      bool stratified);

// The reference's ray-origin offset (app/reference/reference_trace.h, "Origin"), shared with
// stage `raster4d` so that both move a receiver point by the same amount: max(minimum,
// REFERENCE_RELATIVE_OFFSET x the point's largest coordinate), the minimum from the
// occluders' diagonal (referenceMinimumOffset).
#define REFERENCE_RELATIVE_OFFSET 1e-5

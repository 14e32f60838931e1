// raster4d: exclusive prefix sum of the per-FB-pixel counts (count -> prefix sum -> scatter
// builds lists of any length; nothing is dropped). One group: each invocation sums a
// contiguous run, the run totals are scanned in shared memory, then each run is written.
#include "raster4d.glsl"
layout(local_size_x = RASTER4D_SCAN_GROUP) in;
layout(std430, binding = R4D_SCAN_COUNTS) readonly buffer Counts { uint counts[]; };
layout(std430, binding = R4D_SCAN_STARTS) writeonly buffer Starts { uint starts[]; };
shared uint runTotals[RASTER4D_SCAN_GROUP];

void main() {
  uint n = uint(r4d.dispatch.y), invocation = gl_LocalInvocationID.x;
  uint run = (n + RASTER4D_SCAN_GROUP - 1u) / RASTER4D_SCAN_GROUP;
  uint first = min(invocation * run, n), end = min(first + run, n);
  uint total = 0u;
  for (uint i = first; i < end; ++i) total += counts[i];
  runTotals[invocation] = total;
  barrier();
  for (uint offset = 1u; offset < RASTER4D_SCAN_GROUP; offset <<= 1u) {  // Hillis-Steele
    uint add = invocation >= offset ? runTotals[invocation - offset] : 0u;
    barrier();
    runTotals[invocation] += add;
    barrier();
  }
  uint running = runTotals[invocation] - total;  // exclusive
  for (uint i = first; i < end; ++i) {
    starts[i] = running;
    running += counts[i];
  }
  if (invocation == RASTER4D_SCAN_GROUP - 1u) starts[n] = runTotals[invocation];
}

// Stage `trace`, deferred form, last step: the totals of trace_layout.h added up from the
// per-pixel records trace.comp wrote. Each invocation adds up
// TRACE_TOTALS_RECORDS_PER_INVOCATION records and makes one atomicAdd per total.
#include "shared/trace_layout.h"
#include "stages/monte_carlo/classify/classify_layout.h"
layout(local_size_x = 64) in;
layout(std430, binding = TRACE_PARTIALS_BINDING) readonly buffer TracePartials {
  uvec4 partials[];  // TRACE_RECORD_UVEC4S per pixel
};
layout(std430, binding = TRACE_TOTALS_BINDING) buffer TraceTotals { uint totals[TOTAL_COUNT]; };
layout(std430, binding = CLASSIFY_LIST_BINDING) readonly buffer TracedPixels {
  uint listCount;  // the records the listed pixels wrote (classify_layout.h)
};
layout(location = TRACE_TOTALS_RECORDS_LOCATION) uniform uint uRecords;
layout(location = TRACE_TOTALS_FROM_LIST_LOCATION) uniform bool uFromList;

void main() {
  uint first = gl_GlobalInvocationID.x * uint(TRACE_TOTALS_RECORDS_PER_INVOCATION);
  uint records = uFromList ? min(uRecords, listCount) : uRecords;
  uint end = min(first + uint(TRACE_TOTALS_RECORDS_PER_INVOCATION), records);
  if (first >= end) return;
  // rays, searched, early backface, early inside, early region; fetches (all, early outs'),
  // iterations.
  uvec4 small = uvec4(0u);
  uint region = 0u, fetches = 0u, earlyOutFetches = 0u, iterations = 0u;
  for (uint record = first; record < end; ++record) {
    uvec4 counts = partials[record * uint(TRACE_RECORD_UVEC4S)];
    small += uvec4(bitfieldExtract(counts.x, 0, TRACE_COUNT_BITS),
                   bitfieldExtract(counts.x, TRACE_COUNT_BITS, TRACE_COUNT_BITS),
                   bitfieldExtract(counts.x, 2 * TRACE_COUNT_BITS, TRACE_COUNT_BITS),
                   bitfieldExtract(counts.y, 0, TRACE_COUNT_BITS));
    region += bitfieldExtract(counts.y, TRACE_COUNT_BITS, TRACE_COUNT_BITS);
    fetches += counts.z;
    iterations += counts.w;
    earlyOutFetches += partials[record * uint(TRACE_RECORD_UVEC4S) + 1u].x;
  }
  atomicAdd(totals[TOTAL_RAYS], small.x);
  atomicAdd(totals[TOTAL_RAYS_SEARCHED], small.y);
  atomicAdd(totals[TOTAL_EARLY_BACKFACE], small.z);
  atomicAdd(totals[TOTAL_EARLY_INSIDE], small.w);
  atomicAdd(totals[TOTAL_EARLY_REGION], region);
  atomicAdd(totals[TOTAL_FETCHES], fetches);
  atomicAdd(totals[TOTAL_EARLY_OUT_FETCHES], earlyOutFetches);
  atomicAdd(totals[TOTAL_ITERATIONS], iterations);
}

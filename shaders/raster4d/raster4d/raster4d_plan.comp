// raster4d, between STEP 4's counts and the scatters: the plan, on the GPU so that nothing
// waits for a read-back (the stage reads the plan after the frame, for its counters).
//  - The pairs STEP 5 will test: every sample of an FB pixel meets every triangle of its
//    list, so pairs = sum over FB pixels of samples x triangles (exact: whole numbers in
//    double), and the longest triangle list, which sets STEP 5's chunks (each chunk's loop
//    stays under the budget of loop iterations per invocation, raster4d.glsl).
//  - raster4d.budget: STEP 5 runs only if pairs <= the most the budget allows (budget.xy,
//    worked out by the stage with the CPU's own comparison, core/run_control.h); otherwise
//    every command is zero and the stage refuses the run after the frame.
//  - Bands of FB rows whose lists fit in raster4d.max_entries (a row that does not fit gets
//    a band of its own), at most options.z rows each: rows are added to a band while both
//    lists of its rows still fit. Each band slot gets its part of Raster4dParams and the
//    indirect commands of its scatters and STEP 5 (zero past the last band).
// One group: every invocation sums a strided share of the FB pixels, the shares are reduced
// in shared memory; the first invocation then walks the rows (at most 512) and writes the slots.
#include "raster4d.glsl"
layout(local_size_x = RASTER4D_PLAN_GROUP) in;
layout(std430, binding = R4D_PLAN_SAMPLE_COUNTS) readonly buffer SampleCounts { uint sampleCounts[]; };
layout(std430, binding = R4D_PLAN_TRIANGLE_COUNTS) readonly buffer TriangleCounts { uint triangleCounts[]; };
layout(std430, binding = R4D_PLAN_SAMPLE_STARTS) readonly buffer SampleStarts { uint sampleStarts[]; };
layout(std430, binding = R4D_PLAN_TRIANGLE_STARTS) readonly buffer TriangleStarts { uint triangleStarts[]; };
layout(std430, binding = R4D_PLAN_STATE) readonly buffer State { Raster4dState state; };
layout(std430, binding = R4D_PLAN_PLAN) writeonly buffer Plan {
  Raster4dPlan plan;
  Raster4dBandPlan slots[];
};
layout(std430, binding = R4D_PLAN_STEP5_COMMANDS) writeonly buffer Step5Commands { uvec4 step5Commands[]; };

shared double pairsShared[RASTER4D_PLAN_GROUP];
shared uint longestShared[RASTER4D_PLAN_GROUP];

// The groups of a 64-wide pass over `count` items (Raster4dGpu's dispatchLinear, linearIndex).
uvec3 linearGroups(uint count) {
  uint groups = (count + 63u) / 64u;
  if (groups == 0u) return uvec3(0u);
  uint x = min(groups, uint(RASTER4D_MAX_GROUPS));
  return uvec3(x, (groups + x - 1u) / x, 1u);
}

// The first entry of FB row `row` in a prefix sum over the FB pixels.
uint rowStartSamples(int row) { return sampleStarts[row * r4d.sizes.x]; }
uint rowStartTriangles(int row) { return triangleStarts[row * r4d.sizes.x]; }

void main() {
  uint me = gl_LocalInvocationIndex;
  uint cells = uint(r4d.sizes.x * r4d.sizes.y);
  double pairs = 0.0lf;
  uint longest = 0u;
  for (uint cell = me; cell < cells; cell += uint(RASTER4D_PLAN_GROUP)) {
    pairs += double(sampleCounts[cell]) * double(triangleCounts[cell]);
    longest = max(longest, triangleCounts[cell]);
  }
  pairsShared[me] = pairs;
  longestShared[me] = longest;
  barrier();
  for (uint width = uint(RASTER4D_PLAN_GROUP) / 2u; width > 0u; width /= 2u) {
    if (me < width) {
      pairsShared[me] += pairsShared[me + width];
      longestShared[me] = max(longestShared[me], longestShared[me + width]);
    }
    barrier();
  }
  if (me != 0u) return;
  pairs = pairsShared[0];
  longest = longestShared[0];
  bool anyReceiver = state.counts.x > 0u;
  uint chunkSize = uint(r4d.dispatch.w);
  uint chunks = anyReceiver ? (longest + chunkSize - 1u) / chunkSize : 0u;
  bool runs = r4d.budget.z == 0u || pairs <= packDouble2x32(r4d.budget.xy);
  uint maxEntries = uint(r4d.options.y), maxRows = uint(r4d.options.z);
  uint bandSlots = uint(r4d.options.w), commandsPerSlot = r4d.budget.w;
  int rows = r4d.sizes.y;
  uint bands = 0u;
  for (int first = 0; anyReceiver && first < rows; ++bands) {
    int end = first + 1;
    while (end < rows && uint(end - first) < maxRows &&
           rowStartSamples(end + 1) - rowStartSamples(first) <= maxEntries &&
           rowStartTriangles(end + 1) - rowStartTriangles(first) <= maxEntries)
      ++end;
    if (bands < bandSlots) {
      uint sampleBase = rowStartSamples(first), sampleEntries = rowStartSamples(end) - sampleBase;
      uint triangleBase = rowStartTriangles(first);
      Raster4dBandPlan slot;
      slot.band = ivec4(first, end, int(sampleBase), int(triangleBase));
      slot.dispatch = ivec4(int(sampleEntries), 0, int(chunks), int(chunkSize));
      slot.samplesCommand = runs ? uvec4((uint(r4d.sizes.z) + 7u) / 8u, (uint(r4d.sizes.w) + 7u) / 8u, 1u, 0u)
                                 : uvec4(0u);
      slot.trianglesCommand = runs ? uvec4(linearGroups(uint(r4d.modes.w)), 0u) : uvec4(0u);
      slots[bands] = slot;
      uvec3 entryGroups = linearGroups(sampleEntries);
      for (uint k = 0u; k < commandsPerSlot; ++k) {
        uint firstChunk = k * uint(RASTER4D_MAX_GROUPS);
        uint count = chunks > firstChunk ? min(chunks - firstChunk, uint(RASTER4D_MAX_GROUPS)) : 0u;
        bool empty = !runs || count == 0u || entryGroups.x == 0u;
        step5Commands[bands * commandsPerSlot + k] = empty ? uvec4(0u) : uvec4(entryGroups.xy, count, 0u);
      }
    }
    first = end;
  }
  for (uint slot = bands; slot < bandSlots; ++slot) {  // past the last band: nothing to run
    Raster4dBandPlan empty;
    empty.band = ivec4(0);
    empty.dispatch = ivec4(0);
    empty.samplesCommand = uvec4(0u);
    empty.trianglesCommand = uvec4(0u);
    slots[slot] = empty;
    for (uint k = 0u; k < commandsPerSlot; ++k) step5Commands[slot * commandsPerSlot + k] = uvec4(0u);
  }
  uint sampleTotal = sampleStarts[cells], triangleTotal = triangleStarts[cells];
  plan.totals = uvec4(bands, chunks, anyReceiver ? sampleTotal : 0u, anyReceiver ? triangleTotal : 0u);
  plan.pairs = uvec4(unpackDouble2x32(pairs), runs ? 1u : 0u, longest);
}

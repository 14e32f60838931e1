// Stage `classify`, step 2 of 2 (classify.frag is step 1): the class counts, and the list of
// pixels that need rays (penumbra and umbra), so the trace runs over those alone (thesis Fig
// 3.8: "full calculations are only performed in blue areas").
// One pixel per invocation; an 8 x 8 workgroup (screen_pass.glsl) counts its pixels per
// class in shared memory and adds them to the totals once per class, and reserves one run
// of slots in the list for its penumbra pixels and then its umbra pixels.
#include "shared/screen_pass.glsl"
#include "shared/classes.h"
#include "stages/monte_carlo/classify/classify_layout.h"
layout(binding = CLASSIFY_MASK_UNIT) uniform sampler2D classMask;
layout(std430, binding = CLASSIFY_COUNTS_BINDING) buffer ClassifyCountsBlock {
  ClassifyCounts counts;
};
layout(std430, binding = CLASSIFY_LIST_BINDING) buffer TracedPixels {
  uint listCount;      // = penumbra + umbra
  uint traceGroups[3];  // the trace's dispatch: groups covering the list, 1, 1
  uint tracedPixels[];
};
shared uint groupCounts[CLASSIFY_CLASS_COUNT];  // this workgroup's pixels per class
shared uint nextSlot[2];                        // its next penumbra slot, umbra slot

void main() {
  // 1. This invocation's pixel and its class (none past the image's edge).
  ivec2 pixel = screenPixel();
  int pixelClass = pixel.x < 0 ? -1 : int(texelFetch(classMask, pixel, 0).r);
  uint index = gl_LocalInvocationIndex;
  if (index < uint(CLASSIFY_CLASS_COUNT)) groupCounts[index] = 0u;
  memoryBarrierShared();
  barrier();
  // 2. The group's pixels per class, then one addition per class to the totals.
  if (pixelClass >= 0) atomicAdd(groupCounts[pixelClass], 1u);
  memoryBarrierShared();
  barrier();
  if (index < uint(CLASSIFY_CLASS_COUNT) && groupCounts[index] != 0u)
    atomicAdd(counts.pixels[index], groupCounts[index]);
  // 3. The group's slots in the list (penumbra first, then umbra; the order of the groups,
  //    and of the pixels within one, is not deterministic: the trace's result does not
  //    depend on it), and each listed pixel in one of them.
  if (index == 0u) {
    uint traced = groupCounts[CLASS_PENUMBRA] + groupCounts[CLASS_UMBRA];
    nextSlot[0] = traced != 0u ? atomicAdd(listCount, traced) : 0u;
    nextSlot[1] = nextSlot[0] + groupCounts[CLASS_PENUMBRA];
    // The trace's groups reach at least past this group's last slot.
    uint groupSize = uint(CLASSIFY_TRACE_GROUP);
    if (traced != 0u) atomicMax(traceGroups[0], (nextSlot[0] + traced + groupSize - 1u) / groupSize);
  }
  memoryBarrierShared();
  barrier();
  uint xy = uint(pixel.x) | (uint(pixel.y) << 16);
  if (pixelClass == CLASS_PENUMBRA) tracedPixels[atomicAdd(nextSlot[0], 1u)] = xy;
  if (pixelClass == CLASS_UMBRA) tracedPixels[atomicAdd(nextSlot[1], 1u)] = xy;
}

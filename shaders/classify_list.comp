// Stage `classify`, step 2 of 2 (classify.frag is step 1): the class counts, and the list of
// pixels that need rays (penumbra and umbra), so the trace dispatches only those (thesis Fig
// 3.8: "full calculations are only performed in blue areas").
#include "shared/screen_pass.glsl"
#include "shared/classes.h"
#include "shared/classify_layout.h"
layout(binding = CLASSIFY_MASK_UNIT) uniform sampler2D classMask;
layout(std430, binding = CLASSIFY_COUNTS_BINDING) buffer ClassifyCountsBlock {
  ClassifyCounts counts;
};
layout(std430, binding = CLASSIFY_LIST_BINDING) buffer TracedPixels {
  uint listCount;  // = penumbra + umbra
  uint listPadding[3];
  uint tracedPixels[];
};

shared uint groupCounts[CLASSIFY_CLASS_COUNT];
shared uint groupListBase;  // this group's first slot in tracedPixels

void main() {
  uint local = gl_LocalInvocationIndex;
  if (local < uint(CLASSIFY_CLASS_COUNT)) groupCounts[local] = 0u;
  barrier();
  // 1. This pixel's class, and its slot among the group's pixels of that class.
  ivec2 pixel = screenPixel();
  int pixelClass = CLASS_BACKGROUND;
  uint slotInGroup = 0u;
  if (pixel.x >= 0) {
    pixelClass = int(texelFetch(classMask, pixel, 0).r);
    slotInGroup = atomicAdd(groupCounts[pixelClass], 1u);
  }
  barrier();
  // 2. One global atomic per class and group: the counts, and the group's slots in the list
  //    of pixels that need rays (penumbra first, then umbra; the list's order is not
  //    deterministic, the trace's result does not depend on it).
  if (local == 0u)
    groupListBase = atomicAdd(listCount, groupCounts[CLASS_PENUMBRA] + groupCounts[CLASS_UMBRA]);
  if (local < uint(CLASSIFY_CLASS_COUNT) && groupCounts[local] != 0u)
    atomicAdd(counts.pixels[local], groupCounts[local]);
  barrier();
  if (pixelClass == CLASS_PENUMBRA || pixelClass == CLASS_UMBRA) {
    uint slot = groupListBase + slotInGroup +
                (pixelClass == CLASS_UMBRA ? groupCounts[CLASS_PENUMBRA] : 0u);
    tracedPixels[slot] = uint(pixel.x) | (uint(pixel.y) << 16);
  }
}

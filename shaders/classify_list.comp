// Stage `classify`, step 2 of 2 (classify.frag is step 1): the class counts, and the list of
// pixels that need rays (penumbra and umbra), so the trace dispatches only those (thesis Fig
// 3.8: "full calculations are only performed in blue areas").
// One invocation per CLASSIFY_LIST_TILE^2 tile of pixels (tile_pass.glsl), counting in
// registers and listing its penumbra pixels, then its umbra pixels, in scan order.
#include "shared/tile_pass.glsl"
#include "shared/classes.h"
#include "shared/classify_layout.h"
layout(binding = CLASSIFY_MASK_IMAGE, r32f) uniform readonly image2D classMask;
layout(std430, binding = CLASSIFY_COUNTS_BINDING) buffer ClassifyCountsBlock {
  ClassifyCounts counts;
};
layout(std430, binding = CLASSIFY_LIST_BINDING) buffer TracedPixels {
  uint listCount;  // = penumbra + umbra
  uint listPadding[3];
  uint tracedPixels[];
};

void main() {
  // 1. This invocation's tile.
  ivec2 origin = invocationTile(CLASSIFY_LIST_TILE);
  if (origin.x < 0) return;
  ivec2 end = min(origin + CLASSIFY_LIST_TILE, ivec2(frame.sizes.xy));
  // 2. The pixels of each class (separate counters, not an array: llvmpipe would index a
  //    private array lane by lane).
  //    The loops test at their bottom (a tile holds at least one pixel): llvmpipe runs a
  //    loop's body once more, masked, after the last lane leaves by a test at the top
  //    (docs/issue14.md section 17).
  uint background = 0u, lit = 0u, penumbra = 0u, umbra = 0u, outside = 0u;
  int y = origin.y;
  do {
    int x = origin.x;
    do {
      int pixelClass = int(imageLoad(classMask, ivec2(x, y)).r);
      background += pixelClass == CLASS_BACKGROUND ? 1u : 0u;
      lit += pixelClass == CLASS_LIT ? 1u : 0u;
      penumbra += pixelClass == CLASS_PENUMBRA ? 1u : 0u;
      umbra += pixelClass == CLASS_UMBRA ? 1u : 0u;
      outside += pixelClass == CLASS_OUTSIDE ? 1u : 0u;
    } while (++x < end.x);
  } while (++y < end.y);
  if (background != 0u) atomicAdd(counts.pixels[CLASS_BACKGROUND], background);
  if (lit != 0u) atomicAdd(counts.pixels[CLASS_LIT], lit);
  if (penumbra != 0u) atomicAdd(counts.pixels[CLASS_PENUMBRA], penumbra);
  if (umbra != 0u) atomicAdd(counts.pixels[CLASS_UMBRA], umbra);
  if (outside != 0u) atomicAdd(counts.pixels[CLASS_OUTSIDE], outside);
  // 3. The tile's slots in the list (penumbra first, then umbra; the order of the tiles is
  //    not deterministic, the trace's result does not depend on it), and its pixels there.
  //    Tiles without such pixels leave after one pass of the loops' bodies, which lists
  //    nothing there (a loop, not an if: llvmpipe leaves a loop once no lane is in it, but
  //    runs an if's body for all 8 lanes).
  uint traced = penumbra + umbra;
  uint nextPenumbra = traced != 0u ? atomicAdd(listCount, traced) : 0u;
  uint nextUmbra = nextPenumbra + penumbra;
  y = origin.y;
  do {
    int x = origin.x;
    do {
      int pixelClass = int(imageLoad(classMask, ivec2(x, y)).r);
      uint xy = uint(x) | (uint(y) << 16);
      if (pixelClass == CLASS_PENUMBRA) tracedPixels[nextPenumbra++] = xy;
      if (pixelClass == CLASS_UMBRA) tracedPixels[nextUmbra++] = xy;
    } while (++x < end.x && traced != 0u);
  } while (++y < end.y && traced != 0u);
}

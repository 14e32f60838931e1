// The integer window and cell arithmetic of the two depth hierarchies over the light layers,
// compiled by GLSL (nbuffer.glsl, minmax.glsl include it) and by C++ (app/gl/hierarchy_cells.h
// includes it with glm's ivec2, clamp, min, max and findMSB): one text for the
// shaders that build and search the hierarchies and for the window, the builders and the
// tests that reason about them. Written in the subset both languages share: int and ivec2,
// no overloads, no references; CELLS_FN is `inline` in C++ (one definition in many files)
// and nothing in GLSL.
#ifdef __cplusplus
#define CELLS_FN inline
#else
#define CELLS_FN
#endif

// --- The N-buffer (thesis §3.5; layout in nbuffer.glsl) ---

// a_n = 2^n / 2 (a_0 = 0): how far a level-n window starts before its texel.
CELLS_FN int nbufferHalf(int level) { return level == 0 ? 0 : 1 << (level - 1); }

// The smallest level n with 2^n >= texels, ceil(log2(texels)) in integers (0 for one
// texel): a level-n window of the N-buffer, or cell of the min-max mipmap, spans 2^n texels.
CELLS_FN int levelSpanning(int texels) { return texels <= 1 ? 0 : findMSB(texels - 1) + 1; }

// Per axis: the window [lo, hi] (inclusive) of level `level` texel `x` on a map of `size`:
// lo = clamp(x - a_n, 0, max(size - 2^n, 0)), hi = min(lo + 2^n, size) - 1.
CELLS_FN ivec2 nbufferWindow1D(int level, int x, int size) {
  int span = 1 << level;
  int lo = clamp(x - nbufferHalf(level), 0, max(size - span, 0));
  return ivec2(lo, min(lo + span, size) - 1);
}

// The level texel whose window starts at `lo` (clamped inward like the window itself).
// On an axis shorter than 2^level every texel's window is the whole axis: stay in the map.
CELLS_FN int nbufferTexelForWindow(int level, int lo, int size) {
  return min(clamp(lo, 0, max(size - (1 << level), 0)) + nbufferHalf(level), size - 1);
}

// The texel holding the coarsest level's one window, the whole map (level `top`).
CELLS_FN ivec2 nbufferWholeMapTexel(int top, ivec2 size) {
  return ivec2(nbufferTexelForWindow(top, 0, size.x), nbufferTexelForWindow(top, 0, size.y));
}

// --- The min-max mipmap (thesis §5.1; layout in minmax.glsl) ---

// Texels of level `level` along an axis of `size` level-0 texels: ceil(size / 2^level).
CELLS_FN int minmaxLevelSize(int level, int size) { return (size + (1 << level) - 1) >> level; }

// Per axis: the quadtree-aligned cell [lo, hi] (inclusive) of level-0 texels under texel
// `c` of level `level`: [c * 2^n, min((c + 1) * 2^n, size) - 1].
CELLS_FN ivec2 minmaxCell1D(int level, int c, int size) {
  return ivec2(c << level, min((c + 1) << level, size) - 1);
}

// Storage (minmax.glsl): level n >= 1 is mip level n - 1 of one texture, level 0 the layers.
// GL's mip level m has floor(B / 2^m) texels per axis (at least 1), the cells ceil(size / 2^n):
// the base B must cover ceil(size / 2^(m+1)) at every m. With k = levelSpanning(size),
// ceil(size / 2^(k-1)) = 2 for size > 1 forces B >= 2^(k-1), and B = 2^(k-1) covers every level
// (size <= 2^k); no smaller base does, and an exact one (floor = ceil at every level) would need
// ceil(size / 2) itself a power of two. Texels per axis of mip level 0 (level 1), padded:
CELLS_FN int minmaxBaseSize(int size) { return 1 << max(levelSpanning(size) - 1, 0); }

// Mip levels stored: levels 1 .. top (top = levelSpanning(max(W, H))), one texel at the top;
// 1 for a 1 x 1 map (top 0: nothing above the layers; the one texel is never read).
CELLS_FN int minmaxMipLevels(ivec2 size) { return max(levelSpanning(max(size.x, size.y)), 1); }

// The N-buffer (thesis §3.5, after Décoret 2005 and Schwarz & Stamminger 2007).
//
// Storage: a 2D array texture, RGBA32F, the size W x H of the light layers, one layer per
// level n = 0 .. ceil(log2(max(W, H))). Channels: x = zNearMin, y = zNearMax, z = zFarMax
// (linear light depth, frame_block.h), w = 0.
//
// Neighbourhoods. Level n texel (x, y) holds min/max over the window of 2^n x 2^n level-0
// texels "moved approximately to the center" (§3.5) and, where that window would stick
// out of the map, shifted inward so it lies inside (then no information near the edges is
// lost, and every value is exact, not merely conservative). Per axis, with a_n = 2^n / 2
// (a_0 = 0):  lo = clamp(x - a_n, 0, max(W - 2^n, 0)),  window = [lo, min(lo + 2^n, W) - 1].
// Level n is built from level n-1 by 4 fetches per texel, at lo + a_{n-1} and
// lo + 2^(n-1) + a_{n-1} per axis (clamped to the map), whose windows tile this one;
// level 1 (and level 0) straight from the layers' 2x2 texels, in one pass
// (nbuffer_levels01.frag).
//
// A search that wants the level-n window starting at texel `lo` (or ending at it) asks for
// the texel lo + a_n: nbufferTexelForWindow below. Texels outside the map are empty: the
// layers were cleared to near = 1, far = 0 (§3.3).
//
// Distinct windows. Per axis, level n has max(W - 2^n, 0) + 1 different windows,
// held by the texels nbufferTexelForWindow returns, [a_n, a_n + max(W - 2^n, 0)] (clamped to
// the map); the bands of a_n texels at the borders repeat the border windows. Every read of
// the hierarchy (searches, classification, the next level's build) goes through
// nbufferTexelForWindow, so where nobody shows or exports the levels the `nbuffer` stage
// writes the distinct texels only (NBufferTexels::Distinct, app/gl/nbuffer_build.h) from
// level 2 on (levels 0 and 1 are one pass over every texel).

// The arithmetic, shared with C++: nbufferHalf, levelSpanning, nbufferWindow1D,
// nbufferTexelForWindow, nbufferWholeMapTexel.
#include "hierarchy_cells.h"

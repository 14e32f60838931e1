// The min-max mipmap (thesis §5.1's "more conventional image pyramids", the
// "maximum mipmaps" of Tevs et al. 2008): a quadtree over the light layers.
//
// Level n has ceil(W / 2^n) x ceil(H / 2^n) texels; texel c of level n holds
// (zNearMin, zNearMax, zFarMax, 0) over the quadtree-aligned cell of level-0 texels
// [c * 2^n, min((c + 1) * 2^n, size) - 1] per axis, built from its (up to) 2 x 2 children
// in level n-1 (at the borders of odd sizes, only the children that exist). Top level:
// ceil(log2(max(W, H))), one texel over the whole map.
//
// Storage: level 0 is not stored: it is the light layers themselves, (near, near, far),
// read there (trace_ray.glsl hierarchyTexel). Levels n >= 1 are the mip levels of one
// RGBA32F 2D texture (C++: stages/shared_inputs/minmax/minmax_build.h): level n is mip level n - 1, read with
// texelFetch(levels, cell, n - 1). Its base is minmaxBaseSize(W) x minmaxBaseSize(H), the
// next power of two of ceil(W/2) x ceil(H/2) (GL's mips round down, the cells up:
// hierarchy_cells.h says why no smaller base holds every level); texels of a mip level past
// the level's ceil(W / 2^n) x ceil(H / 2^n) are (0, 0, 0, 0), never read
// (docs/decisions/024-minmax-mipmap-levels.md).

// The arithmetic, shared with C++: minmaxLevelSize, minmaxCell1D, minmaxBaseSize,
// minmaxMipLevels.
#include "hierarchy_cells.h"

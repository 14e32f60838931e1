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
// read there (trace_ray.glsl hierarchyTexel). Levels n >= 1 are one RGBA32F 2D texture, an
// atlas (C++: app/gl/minmax_build.h): level n at x = 0, y = the heights of levels 1 .. n-1
// stacked. The atlas is ceil(W/2) x (sum of those heights) texels (1 x 1 for a 1 x 1 map);
// the stored levels use 1/3 of one level.

// The arithmetic, shared with C++: minmaxLevelSize, minmaxCell1D, minmaxLevelOrigin.
#include "hierarchy_cells.h"

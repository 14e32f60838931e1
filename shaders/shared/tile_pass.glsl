// Common head of the per-tile compute passes (issue 14): one invocation per tile x tile
// pixels of the eye image (C++: dispatchTiles in app/gl/shader_program.h). Such a pass
// works on its tile in registers, with no shared memory and no barrier: on llvmpipe a
// pass's shared atomics and barriers cost about 5 ms at 640x480 (bench/llvmpipe-writes).
#include "frame.glsl"
#include "screen_pass_layout.h"
layout(local_size_x = TILE_PASS_GROUP_SIZE) in;

// The lower-left pixel of this invocation's tile, or ivec2(-1) past the last tile.
ivec2 invocationTile(int tile) {
  ivec2 size = ivec2(frame.sizes.xy);
  int tilesX = (size.x + tile - 1) / tile, index = int(gl_GlobalInvocationID.x);
  ivec2 origin = ivec2(index % tilesX, index / tilesX) * tile;
  return origin.y < size.y ? origin : ivec2(-1);
}

// Units and locations of hard_shadow.comp (C++: stages/baselines/hard_shadow.cpp). The
// G-buffer is read through image units (a third of a texelFetch on llvmpipe,
// bench/llvmpipe-reads), the near layer, a depth texture, through a texture unit.
#define HARD_SHADOW_NEAR_UNIT 1
#define HARD_SHADOW_VISIBILITY_IMAGE 0
#define HARD_SHADOW_WS_POSITION_IMAGE 1
#define HARD_SHADOW_WS_NORMAL_IMAGE 2
#define HARD_SHADOW_OFFSET_LOCATION 1  // after ROW_OFFSET_LOCATION

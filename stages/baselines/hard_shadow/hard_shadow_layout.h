// Units and locations of hard_shadow.comp (C++: stages/baselines/hard_shadow/hard_shadow.cpp): the
// G-buffer and the near layer are read with texelFetch, the visibility written as an image.
#define HARD_SHADOW_NEAR_UNIT 1
#define HARD_SHADOW_WS_POSITION_UNIT 2
#define HARD_SHADOW_WS_NORMAL_UNIT 3
#define HARD_SHADOW_VISIBILITY_IMAGE 0
#define HARD_SHADOW_OFFSET_LOCATION 1  // after ROW_OFFSET_LOCATION

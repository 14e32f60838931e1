// Units and locations of hard_shadow.comp (C++: stages/baselines/hard_shadow.cpp).
#define HARD_SHADOW_WS_POSITION_UNIT 0
#define HARD_SHADOW_NEAR_UNIT 1
#define HARD_SHADOW_WS_NORMAL_UNIT 2
#define HARD_SHADOW_VISIBILITY_IMAGE 0
#define HARD_SHADOW_OFFSET_LOCATION 1  // after ROW_OFFSET_LOCATION

// Image units and locations of composite.frag (C++: stages/output/composite.cpp). Read
// through image units, not texture units: on llvmpipe an imageLoad costs a third of a
// texelFetch (bench/llvmpipe-reads).
#define COMPOSITE_ALBEDO_IMAGE 0
#define COMPOSITE_WS_NORMAL_IMAGE 1
#define COMPOSITE_WS_POSITION_IMAGE 2
#define COMPOSITE_VISIBILITY_IMAGE 3
#define COMPOSITE_AMBIENT_LOCATION 1

// Texture units (read with texelFetch) and locations of composite.frag (C++:
// stages/output/composite/composite.cpp).
#define COMPOSITE_ALBEDO_UNIT 0
#define COMPOSITE_WS_NORMAL_UNIT 1
#define COMPOSITE_WS_POSITION_UNIT 2
#define COMPOSITE_VISIBILITY_UNIT 3
#define COMPOSITE_AMBIENT_LOCATION 1

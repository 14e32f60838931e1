// Units and locations of flat_shadow.comp (C++: tests/stages/test_method/flat_shadow.cpp), the
// test-only method of docs/design.md#add-a-method: the G-buffer's positions are read with
// texelFetch, the visibility written as an image.
#define FLAT_SHADOW_WS_POSITION_UNIT 1
#define FLAT_SHADOW_VISIBILITY_IMAGE 0
#define FLAT_SHADOW_LEVEL_LOCATION 1  // after ROW_OFFSET_LOCATION

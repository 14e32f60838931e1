// Every screen-sized compute pass (screen_pass.glsl; C++: dispatchRows in
// app/gl/shader_program.cpp): 8x8 groups, dispatched in row bands whose first row is the
// uniform at this location. Stages' own uniforms start after it.
#define ROW_OFFSET_LOCATION 0


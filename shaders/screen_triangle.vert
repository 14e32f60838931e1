// One triangle covering the viewport (app/gl/screen_triangle.h): corners (-1,-1), (3,-1),
// (-1,3) in clip space from gl_VertexID 0, 1, 2; every texel centre lies inside it once.
// It also hands the frame and light blocks to fragment shaders that read them as flat
// inputs (FRAME_BLOCKS_FROM_VERTEX_STAGE, frame.glsl: why); where a fragment shader does not,
// the linker drops these outputs and the block reads with them.
#include "shared/frame.glsl"
layout(location = FRAME_BLOCKS_LIGHT_LOCATION) flat out LightUniforms vsLight;
layout(location = FRAME_BLOCKS_FRAME_LOCATION) flat out FrameUniforms vsFrame;

void main() {
  vec2 corner = vec2(float((gl_VertexID & 1) << 2), float((gl_VertexID & 2) << 1)) - 1.0;
  gl_Position = vec4(corner, 0.0, 1.0);
  vsLight = light;
  vsFrame = frame;
}

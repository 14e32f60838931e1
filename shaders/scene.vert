// Shared vertex shader: world-space triangles into eye clip space (gbuffer) or light clip
// space (light_layers), chosen by LIGHT_PASS. It also hands the frame and light blocks to
// fragment shaders that read them as flat inputs (FRAME_BLOCKS_FROM_VERTEX_STAGE,
// frame.glsl: why); where a fragment shader does not, the linker drops these outputs.
#include "shared/frame.glsl"
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 0) out vec3 wsPosition;
layout(location = 1) out vec3 wsNormal;
layout(location = FRAME_BLOCKS_LIGHT_LOCATION) flat out LightUniforms vsLight;
layout(location = FRAME_BLOCKS_FRAME_LOCATION) flat out FrameUniforms vsFrame;
void main() {
  wsPosition = inPosition;
  wsNormal = inNormal;
  vsLight = light;
  vsFrame = frame;
#ifdef LIGHT_PASS
  gl_Position = light.lightClipFromWorld * vec4(inPosition, 1.0);
#else
  gl_Position = frame.clipFromWorld * vec4(inPosition, 1.0);
#endif
}

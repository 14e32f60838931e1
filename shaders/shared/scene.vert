// Shared vertex shader: world-space triangles into eye clip space (gbuffer) or light clip
// space (light_layers), chosen by LIGHT_PASS.
#include "shared/frame.glsl"
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 0) out vec3 wsPosition;
layout(location = 1) out vec3 wsNormal;
void main() {
  wsPosition = inPosition;
  wsNormal = inNormal;
#ifdef LIGHT_PASS
  gl_Position = light.lightClipFromWorld * vec4(inPosition, 1.0);
#else
  gl_Position = frame.clipFromWorld * vec4(inPosition, 1.0);
#endif
}

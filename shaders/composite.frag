// Stage `composite` (thesis Algorithm 1, last step): albedo x (ambient + visibility x Lambert).
// A fragment shader over the image (app/gl/screen_triangle.h: why not a compute pass).
#define FRAME_BLOCKS_FROM_VERTEX_STAGE  // frame.glsl: why
#include "shared/frame.glsl"
#include "shared/composite_layout.h"
layout(binding = COMPOSITE_ALBEDO_IMAGE, rgba8) uniform readonly image2D albedoImage;
layout(binding = COMPOSITE_WS_NORMAL_IMAGE, rgba32f) uniform readonly image2D wsNormalImage;
layout(binding = COMPOSITE_WS_POSITION_IMAGE, rgba32f) uniform readonly image2D wsPositionImage;
layout(binding = COMPOSITE_VISIBILITY_IMAGE, r32f) uniform readonly image2D visibilityImage;
layout(location = COMPOSITE_AMBIENT_LOCATION) uniform float uAmbient;  // light that reaches shadowed surfaces
layout(location = 0) out vec4 color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 wsPosition = imageLoad(wsPositionImage, pixel);
  if (wsPosition.w == 0.0) {  // background: a quiet vertical gradient
    float t = float(pixel.y) / float(frame.sizes.y);
    color = vec4(mix(vec3(0.16), vec3(0.30, 0.32, 0.36), t), 1.0);
    return;
  }
  vec3 albedo = imageLoad(albedoImage, pixel).rgb;
  vec3 n = imageLoad(wsNormalImage, pixel).xyz;
  vec3 toLight = light.wsLightCenter.xyz - wsPosition.xyz;
  vec3 l = toLight / max(length(toLight), 1e-20);
  // Lit only from the light's emitting side.
  float lambert = dot(-l, light.wsLightForward.xyz) > 0.0 ? max(dot(n, l), 0.0) : 0.0;
  float visibility = clamp(imageLoad(visibilityImage, pixel).r, 0.0, 1.0);
  color = vec4(albedo * (uAmbient + (1.0 - uAmbient) * visibility * lambert), 1.0);
}

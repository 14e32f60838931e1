// Stage `composite` (thesis Algorithm 1, last step): albedo x (ambient + visibility x Lambert).
// A fragment shader over the image (app/gl/screen_triangle.h: why not a compute pass).
#include "shared/frame.glsl"
#include "stages/output/composite/composite_layout.h"
layout(binding = COMPOSITE_ALBEDO_UNIT) uniform sampler2D albedoImage;
layout(binding = COMPOSITE_WS_NORMAL_UNIT) uniform sampler2D wsNormalImage;
layout(binding = COMPOSITE_WS_POSITION_UNIT) uniform sampler2D wsPositionImage;
layout(binding = COMPOSITE_VISIBILITY_UNIT) uniform sampler2D visibilityImage;
layout(location = COMPOSITE_AMBIENT_LOCATION) uniform float uAmbient;  // light that reaches shadowed surfaces
layout(location = 0) out vec4 color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 wsPosition = texelFetch(wsPositionImage, pixel, 0);
  if (wsPosition.w == 0.0) {  // background: a quiet vertical gradient
    float t = float(pixel.y) / float(frame.sizes.y);
    color = vec4(mix(vec3(0.16), vec3(0.30, 0.32, 0.36), t), 1.0);
    return;
  }
  vec3 albedo = texelFetch(albedoImage, pixel, 0).rgb;
  vec3 n = texelFetch(wsNormalImage, pixel, 0).xyz;
  vec3 toLight = light.wsLightCenter.xyz - wsPosition.xyz;
  vec3 l = toLight / max(length(toLight), 1e-20);
  // Lit only from the light's emitting side.
  float lambert = dot(-l, light.wsLightForward.xyz) > 0.0 ? max(dot(n, l), 0.0) : 0.0;
  float visibility = clamp(texelFetch(visibilityImage, pixel, 0).r, 0.0, 1.0);
  color = vec4(albedo * (uAmbient + (1.0 - uAmbient) * visibility * lambert), 1.0);
}

// Stage `trace`, deferred form (thesis Algorithm 1, step 3): per G-buffer pixel, n x n rays
// through the light's depth layers.
#include "shared/screen_pass.glsl"
#include "shared/trace_pixel.glsl"
#include "shared/classes.h"
layout(binding = 1) uniform sampler2D wsNormalTexture;
layout(binding = 5) uniform sampler2D classMask;
layout(binding = 6) uniform sampler2D zRangeTexture;
layout(binding = 0, r32f) uniform writeonly image2D visibilityImage;
layout(binding = 1, rgba32f) uniform writeonly image2D costImage;

void main() {
  ivec2 pixel = screenPixel();
  if (pixel.x < 0) return;
  gRecording = all(equal(pixel, trace.record.xy));
  vec4 wsPosition = texelFetch(wsPositionTexture, pixel, 0);
  float visibility = 1.0;
  RayCounts counts = RayCounts(0u, 0u, 0u, 0u);
  int pixelClass = int(texelFetch(classMask, pixel, 0).r);
  if (wsPosition.w == 0.0 || pixelClass == CLASS_OUTSIDE) {
    visibility = 1.0;  // background, or outside the light's frustum: nothing known blocks it
  } else if (trace.limits.w != 0 && (pixelClass == CLASS_LIT || pixelClass == CLASS_UMBRA)) {
    visibility = pixelClass == CLASS_LIT ? 1.0 : 0.0;  // classification spares every ray (§3.6)
    atomicAdd(totals[TOTAL_PIXELS_CLASSIFIED], 1u);
    recordStep(-1, STEP_CLASSIFIED, 0, ivec4(-1), vec4(visibility), vec4(0.0));
  } else {
    vec3 wsNormal = texelFetch(wsNormalTexture, pixel, 0).xyz;
    vec4 zRange = texelFetch(zRangeTexture, pixel, 0);  // zNearMin, zNearMax, zFarMax, lsDepth
    visibility = traceVisibility(wsPosition.xyz, wsNormal, pixel, zRange.xz, counts);
    int rays = trace.config.x * trace.config.x;
    addTotals(counts, uint(rays));
  }
  imageStore(visibilityImage, pixel, vec4(visibility));
  imageStore(costImage, pixel, vec4(float(gFetches), float(gIterations), float(counts.searched),
                                    float(counts.backface + counts.inside + counts.region)));
}

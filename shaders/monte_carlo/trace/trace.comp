// Stage `trace`, deferred form (thesis Algorithm 1, step 3): per G-buffer pixel, n x n rays
// through the light's depth layers.
#include "shared/screen_pass.glsl"
#include "shared/trace_pixel.glsl"
#include "shared/classes.h"
#include "stages/monte_carlo/classify/classify_layout.h"
layout(binding = TRACE_MASK_UNIT) uniform sampler2D classMask;    // classify's class
layout(binding = TRACE_ZRANGE_UNIT) uniform sampler2D zRangeImage;  // and its bounds
layout(binding = TRACE_VISIBILITY_IMAGE, r32f) uniform writeonly image2D visibilityImage;
layout(binding = TRACE_COST_IMAGE, rgba32f) uniform writeonly image2D costImage;
layout(std430, binding = CLASSIFY_LIST_BINDING) readonly buffer TracedPixels {
  uint listCount;
  uint traceGroups[3];
  uint tracedPixels[];
};
layout(std430, binding = TRACE_PARTIALS_BINDING) writeonly buffer TracePartials {
  uvec4 partials[];  // TRACE_RECORD_UVEC4S per pixel (trace_layout.h)
};
// TRACE_PIXELS_ALL: every pixel (rows from uRowOffset); _LISTED: the pixels classify listed
// (penumbra, umbra; one invocation per listed pixel, in the groups classify counted for the
// indirect dispatch), everything else was cleared to
// visibility 1 beforehand; _RECORDED: the recorded pixel alone, with its steps (the
// variant compiled with TRACE_RECORDING 1; the others compile the records out).
layout(location = TRACE_PIXELS_LOCATION) uniform int uPixels;

// The pixel, and the index of its record of counts (trace_layout.h).
ivec2 tracedPixel(out uint record) {
  record = 0u;
  if (uPixels == TRACE_PIXELS_ALL) {
    ivec2 pixel = screenPixel();
    record = uint(pixel.y) * frame.sizes.x + uint(pixel.x);
    return pixel;
  }
  if (uPixels == TRACE_PIXELS_RECORDED) {  // nothing where the recorded pixel is off the image
    bool inImage = all(lessThan(uvec2(trace.record.xy), frame.sizes.xy));
    return gl_LocalInvocationIndex == 0u && inImage ? trace.record.xy : ivec2(-1);
  }
  record = gl_WorkGroupID.x * uint(CLASSIFY_TRACE_GROUP) + gl_LocalInvocationIndex;
  if (record >= listCount) return ivec2(-1);
  uint xy = tracedPixels[record];
  return ivec2(int(xy & 0xFFFFu), int(xy >> 16));
}

void main() {
  uint record;
  ivec2 pixel = tracedPixel(record);
  if (pixel.x < 0) return;
  gRecording = uPixels == TRACE_PIXELS_RECORDED;
  vec4 wsPosition = texelFetch(wsPositionTexture, pixel, 0);
  float visibility = 1.0;
  RayCounts counts = RayCounts(0u, 0u, 0u, 0u);
  uint rays = 0u;
  int pixelClass = int(texelFetch(classMask, pixel, 0).r);
  if (wsPosition.w == 0.0 || pixelClass == CLASS_OUTSIDE) {
    visibility = 1.0;  // background, or outside the light's frustum: nothing known blocks it
  } else if (trace.limits.w != 0 && (pixelClass == CLASS_LIT || pixelClass == CLASS_UMBRA)) {
    visibility = pixelClass == CLASS_LIT ? 1.0 : 0.0;  // classification spares every ray (§3.6)
    recordStep(-1, STEP_CLASSIFIED, 0, ivec4(-1), vec4(visibility), vec4(0.0));
  } else {
    vec3 wsNormal = texelFetch(wsNormalTexture, pixel, 0).xyz;
    vec4 zRange = texelFetch(zRangeImage, pixel, 0);  // zNearMin, zNearMax, zFarMax, lsDepth
    visibility = traceVisibility(wsPosition.xyz, wsNormal, pixel, zRange.xz, counts);
    rays = uint(trace.config.x * trace.config.x);
  }
  // The pixel's counts (zero where it traced nothing), for trace_totals.comp. The recorded
  // pixel's second trace is not counted again (the pass over every pixel, or over the
  // listed ones, counted it).
  if (uPixels != TRACE_PIXELS_RECORDED) {
    uint early = counts.backface << (2 * TRACE_COUNT_BITS);
    uint slot = record * uint(TRACE_RECORD_UVEC4S);
    partials[slot] = uvec4(rays | (counts.searched << TRACE_COUNT_BITS) | early,
                           counts.inside | (counts.region << TRACE_COUNT_BITS), gFetches,
                           gIterations);
    partials[slot + 1u] = uvec4(gEarlyOutFetches, 0u, 0u, 0u);
  }
  imageStore(visibilityImage, pixel, vec4(visibility));
#if TRACE_COST  // 0 where nobody shows or exports the cost (stages/monte_carlo/trace/trace.cpp)
  imageStore(costImage, pixel, vec4(float(gFetches), float(gIterations), float(counts.searched),
                                    float(counts.backface + counts.inside + counts.region)));
#endif
}

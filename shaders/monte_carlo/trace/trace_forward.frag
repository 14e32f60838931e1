// Stage `trace`, forward form (for the deferred-vs-forward comparison of thesis Table 4.1):
// every rasterized fragment traces its rays, also those later hidden by nearer ones.
// Without a G-buffer there is no classification and no eye layer (three layers act as
// two); rays are shortened with the bounds of the whole map (the hierarchy's top level).
#include "shared/trace_pixel.glsl"
layout(location = 0) in vec3 wsPosition;
layout(location = 1) in vec3 wsNormal;
layout(location = 0) out float outVisibility;
layout(location = 1) out vec4 outCost;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  gRecording = all(equal(pixel, trace.record.xy));
  vec3 n = normalize(wsNormal);
  if (!gl_FrontFacing) n = -n;
  int topLevel = trace.record.w;
  // Either hierarchy's whole map: the top level's one window.
  ivec2 topTexel = traceHierarchy() == HIERARCHY_MINMAX
                       ? ivec2(0)
                       : nbufferWholeMapTexel(topLevel, ivec2(light.mapSize.xy));
  vec4 whole = hierarchyTexel(topTexel, topLevel);
  RayCounts counts = RayCounts(0u, 0u, 0u, 0u);
  float visibility = 1.0;
  vec3 map = lightMapCoords(wsPosition);
  if (all(greaterThanEqual(map.xy, vec2(0.0))) && all(lessThan(map.xy, vec2(1.0))) &&
      map.z >= light.lightDepthRange.x)
    visibility = traceVisibility(wsPosition, n, pixel, whole.xz, counts);
  addTotals(counts, uint(trace.config.x * trace.config.x));
  outVisibility = visibility;
  outCost = vec4(float(gFetches), float(gIterations), float(counts.searched),
                 float(counts.backface + counts.inside + counts.region));
}

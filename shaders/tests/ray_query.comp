// Runs the trace stage's searches on rays given by the test (see ray_query_layout.h); with
// uEarlyOuts, first the stage's early outs of §3.7 (trace_pixel.glsl: regionIsEmpty,
// endPointInside) as step 4 of traceVisibility runs them with ray shortening off: the ray's
// end point is kept, so the region test decides first and the inside test runs only where
// the region holds something.
#include "../shared/trace_pixel.glsl"
#include "../shared/trace_ray.glsl"
#include "../shared/eye_layer.glsl"
#include "../shared/search_hierarchical.glsl"
#include "../shared/search_linear.glsl"
#include "../shared/ray_query_layout.h"
layout(local_size_x = 64) in;
layout(std430, binding = 2) readonly buffer Queries { RayQuery queries[]; };
layout(std430, binding = 3) writeonly buffer Results { RayQueryResult results[]; };
layout(location = 0) uniform int uCount;
layout(location = 1) uniform int uEarlyOuts;  // bit 0: region test, bit 1: inside test

void main() {
  int index = int(gl_GlobalInvocationID.x);
  if (index >= uCount) return;
  RayQuery query = queries[index];
  Ray ray;
  ray.a = query.ends.xy;
  ray.d = query.ends.zw - query.ends.xy;
  ray.invZa = 1.0 / query.depths.x;
  ray.invZb = 1.0 / query.depths.y;
  ray.wsA = vec3(0.0);
  ray.wsB = vec3(0.0);
  int search = trace.config.z, layers = trace.config.w;
  float sStart = query.depths.z, sEnd = query.depths.w;
  uint ended = RAY_QUERY_SEARCHED;
  bool blocked = false;
  if (uEarlyOuts != 0) {
    RayCounts counts = RayCounts(0u, 0u, 0u, 0u);
    bool regionEmpty = sStart > sEnd || ((uEarlyOuts & 1) != 0 && regionIsEmpty(ray, sStart, sEnd, layers));
    bool inside = (uEarlyOuts & 2) != 0 && !regionEmpty &&
                  endPointInside(ray, sEnd, vec3(0.0), layers, counts);
    gEarlyOutFetches = gFetches;
    if (inside) ended = RAY_QUERY_INSIDE, blocked = true;
    else if (regionEmpty) ended = RAY_QUERY_REGION;
  }
  if (ended == RAY_QUERY_SEARCHED)
    blocked = search == SEARCH_HIERARCHICAL
                  ? searchHierarchical(ray, sStart, sEnd, layers)
                  : searchLinear(ray, sStart, sEnd, layers, search == SEARCH_LINEAR_BINARY);
  results[index].outcome = uvec4((blocked ? 1u : 0u) | (ended << 1u), gFetches, gIterations,
                                 gEarlyOutFetches);
}

// Runs the trace stage's searches on rays given by the test (see ray_query_layout.h).
#include "../shared/trace_ray.glsl"
#include "../shared/eye_layer.glsl"
#include "../shared/search_hierarchical.glsl"
#include "../shared/search_linear.glsl"
#include "../shared/ray_query_layout.h"
layout(local_size_x = 64) in;
layout(std430, binding = 2) readonly buffer Queries { RayQuery queries[]; };
layout(std430, binding = 3) writeonly buffer Results { RayQueryResult results[]; };
layout(location = 0) uniform int uCount;

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
  bool blocked = search == SEARCH_HIERARCHICAL
                     ? searchHierarchical(ray, query.depths.z, query.depths.w, layers)
                     : searchLinear(ray, query.depths.z, query.depths.w, layers,
                                    search == SEARCH_LINEAR_BINARY);
  results[index].outcome = uvec4(blocked ? 1u : 0u, gFetches, gIterations, 0u);
}

// Runs the soft-shadow-map micro-patch functions on queries given by a test.
#include "../shared/ssm_patch.glsl"
#include "../shared/ssm_query_layout.h"
layout(local_size_x = 64) in;
layout(std430, binding = SSM_QUERY_BINDING) readonly buffer Queries { SsmPatchQuery queries[]; };
layout(std430, binding = SSM_RESULT_BINDING) writeonly buffer Results { SsmPatchResult results[]; };
layout(location = 0) uniform int uCount;

void main() {
  int index = int(gl_GlobalInvocationID.x);
  if (index >= uCount) return;
  SsmPatchQuery query = queries[index];
  MicroPatch micro = MicroPatch(query.patchRect.xy, query.patchRect.zw, query.depths.x);
  float occlusion = microPatchOcclusion(micro, query.lsReceiver.xyz, query.depths.zw, query.depths.y);
  results[index].occlusion = vec4(occlusion, 0.0, 0.0, 0.0);
  results[index].extent = penumbraRectAt(micro, query.depths.zw, query.depths.y, query.lsReceiver.w);
}

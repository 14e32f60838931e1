// Test-only micro-patch queries (shaders/tests/ssm_patch_query.comp): one micro-patch and one
// receiver point in light view space (shaders/shared/ssm_patch.glsl), so tests can hold the
// shader's back-projection against the CPU oracle (tests/support/rect_visibility.h).
// std430, storage bindings SSM_QUERY_BINDING (queries, read) and SSM_RESULT_BINDING (results).
#define SSM_QUERY_BINDING 2
#define SSM_RESULT_BINDING 3
struct SsmPatchQuery {
  vec4 patchRect;   // xy = lsMin, zw = lsMax
  vec4 depths;      // x = patch z, y = light plane z (zLight), zw = light half-size
  vec4 lsReceiver;  // xyz, w = virtual-plane z for penumbraRectAt
};
struct SsmPatchResult {
  vec4 occlusion;   // x = microPatchOcclusion, yzw unused
  vec4 extent;      // penumbraRectAt(patch, ..., lsReceiver.w): min.xy, max.xy
};

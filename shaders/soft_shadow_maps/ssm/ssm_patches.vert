// Soft shadow maps, steps 3-4 (Atty et al. 2006 §3.2-3.3, Fig. 3): one instance per texel of
// the occluder map. The texel becomes a micro-patch (§3.2); the quad drawn into the soft
// shadow map covers its penumbra extent (§3.3) for every receiver up to the farthest one.
// Texels without an occluder, and occluders at or behind the light plane, draw nothing.
#include "ssm_common.glsl"
layout(binding = SSM_PATCHES_OCCLUDER_UNIT) uniform sampler2D occluderMap;  // this pass's: nearest or farthest surfaces
layout(std430, binding = DEPTH_BOUNDS_BINDING) readonly buffer Bounds { DepthBounds receivers; };
layout(std430, binding = SSM_WORK_BINDING) buffer Work { SsmWork work; };
layout(location = 0) flat out vec4 vPatchRect;  // micro-patch: lsMin.xy, lsMax.xy
layout(location = 1) flat out float vPatchZ;

void main() {
  int n = ssm.map.x;
  ivec2 texel = ssm.map.w != 0 ? ssm.pick.zw : ivec2(gl_InstanceID % n, gl_InstanceID / n);
  float lsDepth = texelFetch(occluderMap, texel, 0).r;
  bool empty = ssm.map.y == 0 ? lsDepth >= 1.0 : lsDepth <= 0.0;  // cleared values
  if (empty || lsDepth <= 0.0 || receivers.count == 0u) {
    gl_Position = vec4(-2.0, -2.0, 0.0, 1.0);  // all four corners equal: nothing drawn
    return;
  }
  // Step 3 (§3.2): the micro-patch of this texel.
  float z = lsDepthToZ(lsDepth);
  MicroPatch micro = microPatchOfTexel(texel, vec2(n), z, tanHalfFov());
  vPatchRect = vec4(micro.lsMin, micro.lsMax);
  vPatchZ = z;

  // Step 4 (§3.3): the penumbra pyramid cut by the virtual plane through the farthest
  // receiver. Seen from the projection point (map uv = x / z), the cut grows monotonically
  // from the patch's own footprint (a receiver touching the patch) to the virtual plane, so
  // the box around both covers every receiver in between.
  float zVirtual = max(lsDepthToZ(uintBitsToFloat(receivers.maxBits)), z);
  vec4 extent = penumbraRectAt(micro, lightHalfSize(), lightPlaneZ(), zVirtual);
  vec4 uvExtent = extent / (zVirtual * tanHalfFov().xyxy) * 0.5 + 0.5;
  vec4 uvPatch = vec4(vec2(texel), vec2(texel + 1)) / float(n);
  vec4 uvQuad = clamp(vec4(min(uvExtent.xy, uvPatch.xy), max(uvExtent.zw, uvPatch.zw)), 0.0, 1.0);
  // The work: this quad's fragments are the texel centres inside it (x + 0.5 in [lo, hi)),
  // added once per instance, a 64-bit sum (low word and carry), for the cost estimate's check.
  if (ssm.tolerance.y != 0.0 && gl_VertexID == 0) {
    ivec2 lo = ivec2(ceil(uvQuad.xy * float(n) - 0.5));
    ivec2 hi = ivec2(ceil(uvQuad.zw * float(n) - 0.5));
    uint texels = uint(max(hi.x - lo.x, 0)) * uint(max(hi.y - lo.y, 0));
    uint before = atomicAdd(work.low, texels);
    if (before > 0xffffffffu - texels) atomicAdd(work.high, 1u);
  }
  vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);  // triangle strip
  gl_Position = vec4(mix(uvQuad.xy, uvQuad.zw, corner) * 2.0 - 1.0, 0.0, 1.0);
}

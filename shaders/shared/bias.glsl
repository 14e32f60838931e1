// Adaptive bias, thesis Eq 3.2: bias = sqrt(2) z tan(fov/2) / (w (n . l)), the world size
// of a depth-map texel at depth z, stretched by the slope of the surface; n . l is clamped
// away from 0 ("must be limited to some small, non-zero value", §3).
float adaptiveBias(float z, vec3 wsNormal, vec3 wsToLight, float minCosine) {
  float tanHalfFov = max(light.lightDepthRange.z, light.lightDepthRange.w);
  float cosine = max(dot(wsNormal, wsToLight), minCosine);
  return sqrt(2.0) * z * tanHalfFov / (float(light.mapSize.x) * cosine);
}

// Normal offset (light.normal_offset): the receiver point moved along its normal,
// before classify bounds its rays and the trace starts them. The bias of Eq 3.2 shortens a
// ray along itself, which barely moves it off a face the ray runs almost parallel to (a
// box's side face towards the part of the light in front of it): such rays stayed inside
// the box's own near/far interval and were blocked. The full offset is light.bias.w texel
// widths at the point's depth.
// `pointZ` below is the point's distance along the light axis, lightMapCoords(wsPosition).z:
// the caller computes it once (classification needed it up to five times, twice inside a
// loop the compiler does not hoist it out of).
float fullNormalOffset(float pointZ) {
  float tanHalfFov = max(light.lightDepthRange.z, light.lightDepthRange.w);
  return light.bias.w * 2.0 * pointZ * tanHalfFov / float(light.mapSize.x);
}

// The offset is capped by the contact distance: it may bring the point towards the light by
// at most kNormalOffsetGapFraction of the gap between the point and the nearest occluder
// depth its rays can meet (zNearMinLs, linear light depth: classify's Eq 3.3 bound). At a
// coarse map a texel is as wide as a contact gap (128^2: 0.054 against the contact plate's
// 0.06): a full texel plus the Eq 3.2 bias (0.7 texel there) lifted every ray's end above the
// plate and the contact shadow was lost. What moves the point towards the light is the
// offset times -n . forward: a box's side face (n . forward = 0), the case the offset is for,
// keeps all of it; a ground under a plate keeps a quarter of the gap, and the bias the rest.
// An occluder within the Eq 3.2 bias (n . l = 1) of the point is its own surface (a lit box
// top: zNearMin is the top itself), or one the bias alone already passes: no cap there.
const float kNormalOffsetGapFraction = 0.25;
float ownSurfaceBand(float pointZ) {  // Eq 3.2 at n . l = 1, plus the constant bias
  float tanHalfFov = max(light.lightDepthRange.z, light.lightDepthRange.w);
  return light.bias.x + sqrt(2.0) * pointZ * tanHalfFov / float(light.mapSize.x);
}
float occluderGap(float pointZ, float zNearMinLs) {  // light depth, point - zNearMin
  return pointZ - lsDepthToZ(zNearMinLs);
}
float normalOffsetDistance(float pointZ, vec3 wsNormal, float zNearMinLs) {
  float offset = fullNormalOffset(pointZ);
  float towardsLight = -dot(wsNormal, light.wsLightForward.xyz);
  float gap = occluderGap(pointZ, zNearMinLs);
  if (towardsLight > 0.0 && gap > ownSurfaceBand(pointZ))
    offset = min(offset, kNormalOffsetGapFraction * gap / towardsLight);
  return offset;
}
vec3 normalOffsetPoint(vec3 wsPosition, float pointZ, vec3 wsNormal, float zNearMinLs) {
  return wsPosition + wsNormal * normalOffsetDistance(pointZ, wsNormal, zNearMinLs);
}

// Adaptive bias, thesis Eq 3.2: bias = sqrt(2) z tan(fov/2) / (w (n . l)), the world size
// of a depth-map texel at depth z, stretched by the slope of the surface; n . l is clamped
// away from 0 ("must be limited to some small, non-zero value", §3).
float adaptiveBias(float z, vec3 wsNormal, vec3 wsToLight, float minCosine) {
  float tanHalfFov = max(light.lightDepthRange.z, light.lightDepthRange.w);
  float cosine = max(dot(wsNormal, wsToLight), minCosine);
  return sqrt(2.0) * z * tanHalfFov / (float(light.mapSize.x) * cosine);
}

// Normal offset (issue 12; light.normal_offset): the receiver point moved light.bias.w texel
// widths (at its depth) along its normal, before classify bounds its rays and the trace
// starts them. The bias of Eq 3.2 shortens a ray along itself, which barely moves it off a
// face the ray runs almost parallel to (a box's side face towards the part of the light in
// front of it): such rays stayed inside the box's own near/far interval and were blocked.
vec3 normalOffsetPoint(vec3 wsPosition, vec3 wsNormal) {
  float tanHalfFov = max(light.lightDepthRange.z, light.lightDepthRange.w);
  float texelWorld = 2.0 * lightMapCoords(wsPosition).z * tanHalfFov / float(light.mapSize.x);
  return wsPosition + wsNormal * (light.bias.w * texelWorld);
}

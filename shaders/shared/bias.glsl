// Adaptive bias, thesis Eq 3.2: bias = sqrt(2) z tan(fov/2) / (w (n . l)), the world size
// of a depth-map texel at depth z, stretched by the slope of the surface; n . l is clamped
// away from 0 ("must be limited to some small, non-zero value", §3).
float adaptiveBias(float z, vec3 wsNormal, vec3 wsToLight, float minCosine) {
  float tanHalfFov = max(light.lightDepthRange.z, light.lightDepthRange.w);
  float cosine = max(dot(wsNormal, wsToLight), minCosine);
  return sqrt(2.0) * z * tanHalfFov / (float(light.mapSize.x) * cosine);
}

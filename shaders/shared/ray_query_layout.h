// Test-only ray queries (shaders/tests/ray_query.comp): arbitrary rays through the same
// search functions the trace stage uses, so tests can compare them with CPU oracles.
// std430, storage bindings 2 (queries, read) and 3 (results, written).
struct RayQuery {
  vec4 ends;    // xy = A, zw = B (texel space)
  vec4 depths;  // x = zA, y = zB (linear depth along the light axis), z = sStart, w = sEnd
};
struct RayQueryResult {
  uvec4 outcome;  // x = blocked (0/1), y = texel fetches, z = iterations, w unused
};

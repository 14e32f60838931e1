// Test-only ray queries (shaders/tests/ray_query.comp): arbitrary rays through the same
// search functions the trace stage uses, so tests can compare them with CPU oracles.
// std430, storage bindings 2 (queries, read) and 3 (results, written).
struct RayQuery {
  vec4 ends;    // xy = A, zw = B (texel space)
  vec4 depths;  // x = zA, y = zB (linear depth along the light axis), z = sStart, w = sEnd
};
struct RayQueryResult {
  // x = blocked (bit 0) | what ended the ray << 1 (RAY_QUERY_*); y = texel fetches in all;
  // z = iterations; w = the early outs' share of y (0 unless early outs were asked for)
  uvec4 outcome;
};
#define RAY_QUERY_SEARCHED 0u
#define RAY_QUERY_INSIDE 1u
#define RAY_QUERY_REGION 2u

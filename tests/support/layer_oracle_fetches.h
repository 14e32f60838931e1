// What the trace's early outs (thesis §3.7) and its linear search (§2.2) decide on a ray, and
// the texel fetches their rules cost, worked out on the CPU from the layers alone: the
// independent count that the trace's split counters (trace.fetchesEarlyOuts,
// trace.fetchesSearches) are held against (tests/stages/test_trace_oracle.cpp). It shares no
// code with the shaders: the layers are read texel by texel, the region's bounds are a
// brute-force min/max over the window's texels (not the N-buffer), all in double.
//
// THE RULES COUNTED (what one fetch is, as trace_ray.glsl counts them):
// - a texel of the two layers is two fetches (near and far), a texel of the N-buffer one;
// - region test ("nothing in the ray's region can block it", lit): one N-buffer texel, the
//   level-L window with 2^L >= the side of the texel rectangle the ray's [sStart, sEnd]
//   spans, starting at that rectangle's low corner (moved back inside the map where it would
//   stick out); the ray is lit when its depth at sEnd is above every near in the window, or
//   its depth at sStart below every far. Costs 1 whenever it runs (sStart <= sEnd);
// - inside test ("the end point inside a solid", blocked): the layers at the end point's
//   texel; near <= depth <= far. Costs 2; with the ray's end kept (no shortening) it runs
//   only where the region test did not end the ray;
// - linear search: samples at s_k = sStart + k (sEnd - sStart) / n, k = 0..n, n = ceil(the
//   projected length in texels / step) (at least 1, at most maxSteps), each costing 2 (its
//   texel's layers), until the first that blocks: between near and far, or the second of two
//   samples in one texel that went from in front of near to behind far (a sheet crossed).
// Float decisions within ~1e-5 of a threshold (a texel edge, a layer depth, a whole sample
// count) are flagged ambiguous: the GPU's float may take either side.
#pragma once
#include "support/layer_oracle.h"

struct OracleEarlyOuts {
  bool regionEmpty = false;  // the region test ended the ray: lit
  bool inside = false;       // the inside test ended the ray: blocked
  int fetches = 0;           // what the tests that ran cost
  bool ambiguous = false;
};
OracleEarlyOuts oracleEarlyOuts(const LayerMaps& maps, const OracleRay& ray, float zNear,
                                float zFar, double sStart, double sEnd, bool regionTest,
                                bool insideTest);

struct OracleSearch {
  bool blocked = false;
  int fetches = 0;
  int samples = 0;
  bool ambiguous = false;
};
OracleSearch oracleLinearSearch(const LayerMaps& maps, const OracleRay& ray, float zNear,
                                float zFar, double sStart, double sEnd, double stepTexels,
                                int maxSteps);

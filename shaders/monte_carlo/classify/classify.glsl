// Penumbra classification helpers (thesis §3.6, Eq 3.3, Fig 3.7), shared by stage
// `classify` and any pass that wants occluder bounds over a region of the light map.
// Needs frame.glsl, nbuffer.glsl and minmax.glsl included before.

// The texel rectangle (lo.xy, hi.xy, inclusive) that any ray from any point of the light to
// a receiver can cross at light depths >= occluderZ (linear distances along the light
// axis; receiverZ > zNear). Derivation (Fig 3.7): the light covers the whole map at depth
// n = zNear, so a ray from light point uL (map coords) to the receiver at map coords B
// crosses depth d at (1 - s) uL + s B with s = z (d - n) / (d (z - n)); over all uL that is
// a square of side size = 1 - s = n (z - d) / (d (z - n)) (Eq 3.3) and lower corner s B.
// The squares shrink towards B as d grows, each inside the one before, so the square at
// d = occluderZ holds every crossing at depths >= occluderZ.
ivec4 reachableTexels(vec2 receiverUv, float receiverZ, float occluderZ, ivec2 mapSize) {
  float n = light.lightDepthRange.x;
  float size = clamp(n * (receiverZ - occluderZ) / (occluderZ * (receiverZ - n)), 0.0, 1.0);
  vec2 lo = (1.0 - size) * clamp(receiverUv, 0.0, 1.0) * vec2(mapSize);
  vec2 hi = lo + size * vec2(mapSize);
  // Closed square: a corner on a texel border touches both texels; the margin absorbs
  // float rounding (a hundredth of a texel, conservative).
  const float margin = 0.01;
  return ivec4(clamp(ivec2(floor(lo - margin)), ivec2(0), mapSize - 1),
               clamp(ivec2(floor(hi + margin)), ivec2(0), mapSize - 1));
}

// (min zNearMin, max zNearMax, max zFarMax) over the texel rectangle [lo, hi] from 4
// N-buffer fetches: at the level whose window is just under the rectangle's longer side,
// two windows per axis, one starting at lo and one ending at hi, cover it exactly (for a
// square map and square rectangle; a superset otherwise, still conservative).
vec3 nbufferBoundsOverRect(sampler2DArray levels, ivec2 lo, ivec2 hi) {
  ivec3 size = textureSize(levels, 0);
  int extent = max(hi.x - lo.x, hi.y - lo.y) + 1;
  // Smallest level with 2^(level+1) >= extent; level 0 for a single texel.
  int level = extent <= 1 ? 0 : findMSB(extent - 1);
  level = min(level, size.z - 1);
  int span = 1 << level;
  ivec2 secondLo = max(hi - span + 1, lo);
  // nbufferTexelForWindow can point past the map where the map is narrower than 2^level
  // (non-square maps); the clamped texel's window is the same (the whole axis).
  ivec2 first = min(ivec2(nbufferTexelForWindow(level, lo.x, size.x),
                          nbufferTexelForWindow(level, lo.y, size.y)), size.xy - 1);
  ivec2 second = min(ivec2(nbufferTexelForWindow(level, secondLo.x, size.x),
                           nbufferTexelForWindow(level, secondLo.y, size.y)), size.xy - 1);
  vec4 a = texelFetch(levels, ivec3(first, level), 0);
  vec4 b = texelFetch(levels, ivec3(second.x, first.y, level), 0);
  vec4 c = texelFetch(levels, ivec3(first.x, second.y, level), 0);
  vec4 d = texelFetch(levels, ivec3(second, level), 0);
  return vec3(min(min(a.x, b.x), min(c.x, d.x)), max(max(a.y, b.y), max(c.y, d.y)),
              max(max(a.z, b.z), max(c.z, d.z)));
}

// The bounds over the whole map: the coarsest level's one window.
vec3 nbufferWholeMap(sampler2DArray levels) {
  ivec3 size = textureSize(levels, 0);
  return texelFetch(levels, ivec3(nbufferWholeMapTexel(size.z - 1, size.xy), size.z - 1), 0).xyz;
}

// The same bounds from the min-max mipmap: conservative, not exact. At the finest
// level whose aligned cells cover [lo, hi] with at most `cells` of them per axis, min/max
// over those cells: they hold the rectangle, so zNearMin can only be lower and the maxima
// higher than over the rectangle itself; a pixel can move from lit or umbra to penumbra,
// never back (tests/stages/test_classify.cpp counts how many). More cells per axis: a
// finer level, a cover closer to the rectangle, more fetches (up to cells^2). Level 0 is the
// layers (near, near, far), not stored; level n >= 1 is mip level n - 1 (minmax.glsl).
vec3 minmaxBoundsOverRect(sampler2D minmaxLevels, sampler2D nearLayer, sampler2D farLayer, ivec2 lo,
                          ivec2 hi, ivec2 mapSize, int cells) {
  int top = levelSpanning(max(mapSize.x, mapSize.y));
  // (hi >> L) - (lo >> L) >= (hi - lo) >> L, so no level below the smallest with
  // ((hi - lo) >> L) <= cells - 1 can do; from there at most one more step is needed.
  int spread = max(hi.x - lo.x, hi.y - lo.y);
  int level = min(spread < cells ? 0 : findMSB(spread / cells) + 1, top);
  while (level < top && any(greaterThan((hi >> level) - (lo >> level), ivec2(cells - 1)))) ++level;
  ivec2 first = lo >> level, last = hi >> level;
  vec3 bounds = vec3(1.0, 0.0, 0.0);  // empty: near = 1, far = 0 (§3.3)
  if (level == 0) {  // single texels: the layers themselves, (near, near, far)
    for (int y = first.y; y <= last.y; ++y)
      for (int x = first.x; x <= last.x; ++x) {
        float nearDepth = texelFetch(nearLayer, ivec2(x, y), 0).r;
        bounds = vec3(min(bounds.x, nearDepth), max(bounds.y, nearDepth),
                      max(bounds.z, texelFetch(farLayer, ivec2(x, y), 0).r));
      }
    return bounds;
  }
  for (int y = first.y; y <= last.y; ++y)
    for (int x = first.x; x <= last.x; ++x) {
      vec3 cell = texelFetch(minmaxLevels, ivec2(x, y), level - 1).xyz;
      bounds = vec3(min(bounds.x, cell.x), max(bounds.yz, cell.yz));
    }
  return bounds;
}

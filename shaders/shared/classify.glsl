// Penumbra classification helpers (thesis §3.6, Eq 3.3, Fig 3.7), shared by stage
// `classify` and any pass that wants occluder bounds over a region of the light map.
// Needs frame.glsl and nbuffer.glsl included before.

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

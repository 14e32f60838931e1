// Hierarchical search through the N-buffer: thesis Algorithm 2 (§3.5); or through the
// min-max mipmap, the same ascent and descent on quadtree-aligned cells.
// State: the stepping s (the searched part of the ray is [sStart, s]), the texel `cell`
// that contains P(s), and a level. Each iteration looks at the level's window that holds
// `cell` and as much of the forward ray as possible, and asks whether the ray's depth over
// its part inside the window, [lsDepth(s), lsDepth(sExit)], meets [zNearMin, zFarMax]:
//   yes, level 0: the ray passes between the layers in one texel: a hit (terminal case 1);
//   yes, coarser: advance s to where the ray reaches zNearMin (nothing nearer can block it)
//                 and descend one level;
//   no:           advance s to the window's exit and ascend one level;
//   s past the end: a miss (terminal case 2).
// `cell` advances by whole texels at window exits, so every iteration makes progress even
// when s lands exactly on a texel boundary.

// The window [lo, hi] per axis at `level` holding `cell`: N-buffer, extending in the ray's
// direction; min-max mipmap, the aligned cell (texel cell >> level of that level).
ivec4 forwardWindow(ivec2 cell, int level, vec2 direction, out ivec2 texel) {
  ivec2 size = ivec2(light.mapSize.xy);
  if (traceHierarchy() == HIERARCHY_MINMAX) {
    texel = cell >> level;
    ivec2 lo = texel << level;
    return ivec4(lo, min(lo + (1 << level), size) - 1);
  }
  int span = 1 << level;
  ivec4 window;
  for (int axis = 0; axis < 2; ++axis) {
    int lo = direction[axis] >= 0.0 ? cell[axis] : cell[axis] - span + 1;
    texel[axis] = nbufferTexelForWindow(level, lo, size[axis]);
    ivec2 range = nbufferWindow1D(level, texel[axis], size[axis]);
    window[axis] = range.x;
    window[axis + 2] = range.y;
  }
  return window;
}

// The s where the ray leaves `window` forwards, and which axes it leaves through (a slab
// test): per axis, the edge the ray moves towards, then one division; the nearer of the
// two axes' exits is the window's. An axis the ray does not move along is never left (1e30).
float windowExit(Ray ray, ivec4 window, out bvec2 exitAxes) {
  vec2 edge = mix(vec2(window.xy), vec2(window.zw + 1), greaterThan(ray.d, vec2(0.0)));
  vec2 tAxis = mix(vec2(1e30), (edge - ray.a) / ray.d, notEqual(ray.d, vec2(0.0)));
  float sExit = min(tAxis.x, tAxis.y);
  exitAxes = equal(tAxis, vec2(sExit));
  return sExit;
}

// Returns true when the ray [sStart, sEnd] is blocked. layers: 1 = behind the near layer is
// solid; 2 = between near and far is solid; 3 = as 2, but a hit must also be hidden from
// the eye, else the search steps past that texel.
bool searchHierarchical(Ray ray, float sStart, float sEnd, int layers) {
  bool threeLayers = layers == 3;
  int topLevel = trace.record.w;
  vec2 extent = abs(ray.d) * (sEnd - sStart);
  int level = clamp(int(ceil(log2(max(extent.x, extent.y) + 2.0))), 0, topLevel);
  float s = sStart;
  // The ray's depth at s, carried rather than recomputed: after advancing to the crossing
  // with zNearMin it is exactly zNearMin, which rayLsDepth(s) might miss by a rounding step
  // (and so miss a zero-thickness sheet, near == far).
  float depthAtS = rayLsDepth(ray, s);
  ivec2 cell = texelAt(rayPoint(ray, s));
  for (int iteration = 0; iteration < trace.limits.x; ++iteration) {
    gIterations += 1u;
    ivec2 texel;
    ivec4 window = forwardWindow(cell, level, ray.d, texel);
    vec4 bounds = fetchHierarchy(texel, level);
    if (layers == 1) bounds.z = 1.0;  // one layer: everything behind the near layer is solid
    bvec2 exitAxes;
    float sExit = min(windowExit(ray, window, exitAxes), sEnd);
    float depthIn = depthAtS, depthOut = rayLsDepth(ray, sExit);
    bool mayHit = depthOut >= bounds.x && depthIn <= bounds.z;
    if (mayHit && level == 0) {
      bool hit = !threeLayers;
      if (threeLayers) {
        // Test both ends of the texel's part of the ray that lies in [near, far]: where it
        // enters (at the near surface or the texel's edge) and where it leaves (at the far
        // surface or the edge). Testing the entry alone let a ray that entered in free space
        // the eye sees (between two stacked plates) skip the far surface it meets in the
        // same texel.
        float sIn = depthIn < bounds.x ? raySAtLsDepth(ray, bounds.x) : s;
        float sOut = depthOut > bounds.z ? raySAtLsDepth(ray, bounds.z) : sExit;
        hit = hiddenFromEye(rayWorldPoint(ray, clamp(sIn, s, sExit))) ||
              hiddenFromEye(rayWorldPoint(ray, clamp(sOut, s, sExit)));
      }
      recordStep(level, hit ? STEP_HIT : STEP_EYE_VISIBLE, iteration, window,
                 vec4(bounds.x, bounds.z, depthIn, depthOut), vec4(s, s, rayPoint(ray, s)));
      if (hit) return true;
      mayHit = false;  // free space seen by the eye: leave this texel
    }
    if (mayHit) {
      float sBefore = s;
      if (depthIn < bounds.x) {
        s = clamp(raySAtLsDepth(ray, bounds.x), s, sExit);
        depthAtS = bounds.x;
        ivec2 moved = texelAt(rayPoint(ray, s));
        cell = clamp(moved, window.xy, window.zw);
      }
      recordStep(level, STEP_DESCEND, iteration, window,
                 vec4(bounds.x, bounds.z, depthIn, depthOut), vec4(sBefore, s, rayPoint(ray, s)));
      level -= 1;
      continue;
    }
    recordStep(level, STEP_ADVANCE, iteration, window,
               vec4(bounds.x, bounds.z, depthIn, depthOut), vec4(s, sExit, rayPoint(ray, sExit)));
    if (sExit >= sEnd) {
      recordStep(level, STEP_MISS, iteration, window, vec4(bounds.x, bounds.z, depthIn, depthOut),
                 vec4(sExit, sExit, rayPoint(ray, sExit)));
      return false;
    }
    // Step into the neighbouring texel across the exit face(s); stay in line elsewhere.
    ivec2 next = clamp(ivec2(floor(rayPoint(ray, sExit))), window.xy, window.zw);
    for (int axis = 0; axis < 2; ++axis)
      if (exitAxes[axis]) next[axis] = ray.d[axis] > 0.0 ? window[axis + 2] + 1 : window[axis] - 1;
    if (any(lessThan(next, ivec2(0))) || any(greaterThanEqual(next, ivec2(light.mapSize.xy)))) {
      recordStep(level, STEP_MISS, iteration, window, vec4(bounds.x, bounds.z, depthIn, depthOut),
                 vec4(sExit, sExit, rayPoint(ray, sExit)));
      return false;  // left the map: nothing beyond
    }
    s = sExit;
    depthAtS = depthOut;
    cell = next;
    level = min(level + 1, topLevel);
  }
  atomicAdd(totals[TOTAL_ITERATION_CAP], 1u);
  return true;  // cap reached (counted; the tests require it never happens)
}

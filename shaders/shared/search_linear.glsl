// Linear and linear/binary search (thesis §2.2, §3.2-3.4): samples every `trace.stepping.x`
// texels along the projected ray.
//   one layer:   a sample behind the near layer is a hit (§3.2; aliases, cannot refine);
//   two layers:  a sample between near and far is a hit (§3.3);
//   three layers: ... unless the eye sees that point (§3.4).
// With binary refinement (linear_binary), a state change between two samples that may hide
// a crossing of the solid is bisected `trace.limits.y` times; if no hit is found, the
// search goes on linearly from the farther sample (§3.3). The thesis names transitions *to*
// an in-front state or *from* a behind state, walking from the receiver towards the light;
// we walk from the light (depth increasing), so the same transitions read backwards: *from*
// in front, or *to* behind. Where two samples in the same texel go from in front to behind,
// the ray's depth (monotone along the ray) passed through [near, far] between them: a hit,
// which is how a zero-thickness sheet (near == far) is ever found by sampling.

struct LayerState { bool inFront, behind; ivec2 texel; float s; };

// An empty texel (near 1, far 0 as cleared: near > far) is neither: the ray passing over
// empty map is no transition, else every ray would refine at its first step.
LayerState layerState(vec2 layers, float depth, ivec2 texel, float s) {
  if (layers.x > layers.y) return LayerState(false, false, texel, s);
  return LayerState(depth < layers.x, depth > layers.y, texel, s);
}
bool isSuspicious(LayerState from, LayerState to) {
  return (from.inFront && !to.inFront) || (to.behind && !from.behind);
}

// Whether the ray crossed the solid of one texel between two samples (two or three layers;
// three: the crossing's midpoint must be hidden from the eye).
bool crossedBetween(Ray ray, LayerState a, LayerState b, int layers) {
  if (layers < 2 || any(notEqual(a.texel, b.texel)) || !a.inFront || !b.behind) return false;
  return layers == 2 || hiddenFromEye(rayWorldPoint(ray, 0.5 * (a.s + b.s)));
}

// Whether the sample at s blocks the ray, and its state.
bool sampleBlocks(Ray ray, float s, int layers, out LayerState state) {
  ivec2 texel = texelAt(rayPoint(ray, s));
  vec2 layers2 = fetchLayers(texel);
  float depth = rayLsDepth(ray, s);
  state = layerState(layers2, depth, texel, s);
  if (layers == 1) return depth >= layers2.x;
  if (depth < layers2.x || depth > layers2.y) return false;  // not between near and far
  return layers == 2 || hiddenFromEye(rayWorldPoint(ray, s));
}

bool searchLinear(Ray ray, float sStart, float sEnd, int layers, bool refine) {
  float lengthTexels = length(ray.d) * (sEnd - sStart);
  int steps = clamp(int(ceil(lengthTexels / trace.stepping.x)), 1, trace.limits.x);
  float ds = (sEnd - sStart) / float(steps);
  LayerState previous;
  float sPrevious = sStart;
  bool blocked = sampleBlocks(ray, sStart, layers, previous);
  for (int k = 0; k <= steps; ++k) {
    gIterations += 1u;
    float s = k == 0 ? sStart : sStart + float(k) * ds;
    LayerState current;
    if (k > 0) blocked = sampleBlocks(ray, s, layers, current) || crossedBetween(ray, previous, current, layers);
    else current = previous;
    recordStep(-1, blocked ? STEP_HIT : STEP_SAMPLE, k, ivec4(texelAt(rayPoint(ray, s)), texelAt(rayPoint(ray, s))),
               vec4(0.0, 0.0, rayLsDepth(ray, s), rayLsDepth(ray, s)), vec4(sPrevious, s, rayPoint(ray, s)));
    if (blocked) return true;
    if (refine && k > 0 && layers >= 2 && isSuspicious(previous, current)) {
      float lo = sPrevious, hi = s;
      LayerState loState = previous, hiState = current;
      for (int i = 0; i < trace.limits.y; ++i) {
        float mid = 0.5 * (lo + hi);
        LayerState midState;
        bool midBlocks = sampleBlocks(ray, mid, layers, midState) ||
                         crossedBetween(ray, loState, midState, layers) ||
                         crossedBetween(ray, midState, hiState, layers);
        recordStep(-1, midBlocks ? STEP_HIT : STEP_REFINE, k, ivec4(texelAt(rayPoint(ray, mid)), texelAt(rayPoint(ray, mid))),
                   vec4(0.0, 0.0, rayLsDepth(ray, mid), rayLsDepth(ray, mid)), vec4(lo, mid, rayPoint(ray, mid)));
        if (midBlocks) return true;
        // Keep the half that still holds the suspicious transition.
        if (isSuspicious(loState, midState)) { hi = mid; hiState = midState; }
        else { lo = mid; loState = midState; }
      }
    }
    previous = current;
    sPrevious = s;
  }
  recordStep(-1, STEP_MISS, steps, ivec4(-1), vec4(0.0), vec4(sEnd, sEnd, rayPoint(ray, sEnd)));
  return false;
}

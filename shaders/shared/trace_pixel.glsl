// Visibility of the light from one receiver point: n x n rays to random points of the
// light (§3.1), each with the early outs of §3.7, shortened (§3.7, Fig 3.9) and searched
// (§3.3-3.5). Shared by the deferred compute pass and the forward raster pass.
#include "trace_ray.glsl"
#include "eye_layer.glsl"
#include "bias.glsl"
#include "hash.glsl"
#include "search_hierarchical.glsl"
#include "search_linear.glsl"

// Light sample in [0,1)^2 over the light: seeded by the screen coordinates and the ray
// index, scrambled by the frame key (Appendix A); jittered: one sample per grid cell (§3.1).
vec2 lightSampleUnit(ivec2 pixel, int rayIndex, int raysPerSide) {
  uvec4 bits = hashRand(uvec4(uint(pixel.x), uint(pixel.y), uint(rayIndex), 0u), frame.keys.x,
                        int(light.sampling.x));
  vec2 r = toUnitSquare(bits.xy);
  if (trace.config.y == SAMPLING_RANDOM) return r;
  return (vec2(rayIndex % raysPerSide, rayIndex / raysPerSide) + r) / float(raysPerSide);
}

vec3 lightSampleWorld(vec2 unit) {
  return light.wsLightCenter.xyz + (2.0 * unit.x - 1.0) * light.wsLightRight.w * light.wsLightRight.xyz
                                 + (2.0 * unit.y - 1.0) * light.wsLightUp.w * light.wsLightUp.xyz;
}

// Early out "the ray's region holds no occluder" (§3.7): one N-buffer fetch at the level
// whose window covers the ray's whole projection; with the min-max mipmap, the (at most
// 2 x 2) aligned cells of the level whose cell size covers it.
bool regionIsEmpty(Ray ray, float sStart, float sEnd, int layers) {
  vec2 p0 = rayPoint(ray, sStart), p1 = rayPoint(ray, sEnd);
  ivec2 lo = texelAt(min(p0, p1)), hi = texelAt(max(p0, p1));
  int span = max(hi.x - lo.x, hi.y - lo.y) + 1;
  int level = min(levelSpanning(span), trace.record.w);
  ivec2 size = ivec2(light.mapSize.xy);
  vec4 bounds;
  if (traceHierarchy() == HIERARCHY_MINMAX) {
    ivec2 first = lo >> level, last = hi >> level;
    bounds = vec4(1.0, 0.0, 0.0, 0.0);  // empty: near = 1, far = 0 (§3.3)
    for (int y = first.y; y <= last.y; ++y)
      for (int x = first.x; x <= last.x; ++x) {
        vec4 b = fetchHierarchy(ivec2(x, y), level);
        bounds = vec4(min(bounds.x, b.x), max(bounds.y, b.y), max(bounds.z, b.z), 0.0);
      }
  } else {
    bounds = fetchHierarchy(ivec2(nbufferTexelForWindow(level, lo.x, size.x),
                                  nbufferTexelForWindow(level, lo.y, size.y)), level);
  }
  float depthIn = rayLsDepth(ray, sStart), depthOut = rayLsDepth(ray, sEnd);
  float farBound = layers == 1 ? 1.0 : bounds.z;
  return depthOut < bounds.x || depthIn > farBound;
}

struct RayCounts { uint searched, backface, inside, region; };

// Early out "the end point inside a solid" (§3.7): the ray's receiver end lies between the
// layers at its texel (one layer: behind the near layer; three: and hidden from the eye).
bool endPointInside(Ray ray, float sEndPoint, vec3 wsEnd, int layers, inout RayCounts counts) {
  ivec2 texel = texelAt(rayPoint(ray, sEndPoint));
  vec2 endLayers = fetchLayers(texel);
  float endDepth = rayLsDepth(ray, sEndPoint);
  bool inside = layers == 1 ? endDepth >= endLayers.x
                            : endDepth >= endLayers.x && endDepth <= endLayers.y &&
                                  (layers == 2 || hiddenFromEye(wsEnd));
  if (inside) {
    counts.inside += 1u;
    recordStep(0, STEP_EARLY_INSIDE, 0, ivec4(texel, texel), vec4(endLayers, endDepth, endDepth),
               vec4(sEndPoint, sEndPoint, rayPoint(ray, sEndPoint)));
  }
  return inside;
}

// zBounds: (zNearMin, zFarMax) over every texel any of this point's rays can cross
// (classify's Eq 3.3 region; the whole map where no classification ran).
float traceVisibility(vec3 wsPosition, vec3 wsNormal, ivec2 pixel, vec2 zBounds,
                      inout RayCounts counts) {
  int raysPerSide = trace.config.x, layers = traceLayers(), search = traceSearch();
  int rayCount = raysPerSide * raysPerSide;
  int unblocked = 0;
  // Capped by zNearMin.
  wsPosition = normalOffsetPoint(wsPosition, lightMapCoords(wsPosition).z, wsNormal, zBounds.x);
  float receiverZ = lightMapCoords(wsPosition).z;
  for (int i = 0; i < rayCount; ++i) {
    gRayIndex = i;
    // 1. The ray: light sample -> receiver, shortened at the receiver by the bias (Eq 3.2).
    vec3 wsLightSample = lightSampleWorld(lightSampleUnit(pixel, i, raysPerSide));
    vec3 toLight = wsLightSample - wsPosition;
    float distanceToLight = length(toLight);
    vec3 direction = toLight / max(distanceToLight, 1e-20);
    if (trace.switches.x != 0 && dot(wsNormal, direction) <= 0.0) {
      counts.backface += 1u;
      recordStep(-1, STEP_EARLY_BACKFACE, 0, ivec4(-1), vec4(0.0), vec4(0.0));
      continue;  // 2. early out: the sample is behind the surface (§3.7)
    }
    float bias = light.bias.x;
    if (light.bias.y != 0.0) bias += adaptiveBias(receiverZ, wsNormal, direction, light.bias.z);
    vec3 wsEnd = wsPosition + direction * min(bias, 0.999 * distanceToLight);
    Ray ray = makeRay(wsLightSample, wsEnd);
    float sStart = 0.0, sEnd = 1.0;
    if (ray.invZb >= ray.invZa || !clipToMap(ray, sStart, sEnd)) {
      ++unblocked;  // not beyond the light plane, or outside the map: nothing known blocks it
      recordStep(-1, STEP_MISS, 0, ivec4(-1), vec4(0.0), vec4(0.0));
      continue;
    }
    // 3. Ray shortening to [zNearMin, zFarMax] (§3.7, Fig 3.9); one layer keeps its far end
    //    (behind the near layer is solid however deep).
    //    The band is widened by kShortenMargin: nothing can block the ray outside
    //    [zNearMin, zFarMax], so the margin costs nothing, and a zero-thickness occluder
    //    (zNearMin == zFarMax) keeps a ray of non-zero length through it.
    float sEndPoint = sEnd;  // the receiver end, which the inside test reads
    if (trace.switches.w != 0) {
      const float kShortenMargin = 1e-4;
      sStart = max(sStart, raySAtLsDepth(ray, zBounds.x - kShortenMargin));
      if (layers >= 2) sEnd = min(sEnd, raySAtLsDepth(ray, zBounds.y + kShortenMargin));
    }
    // 4. Early outs (§3.7): the end point inside a solid (blocked; one level-0 fetch) and
    //    nothing in the ray's region can block it (lit; one hierarchy fetch, min-max up to
    //    4). Their fetches are counted apart from the search's (gEarlyOutFetches). The
    //    region test runs first, for every ray, since it ends far more rays (cube 640x480:
    //    59,630 against none), and decides first where that cannot change a decision:
    //    - shortening kept the end point: the region test's rectangle covers the end texel,
    //      and inside means near <= its depth <= far there, so the ray's last depth is not
    //      above zNearMin nor its first below zFarMax: the region test cannot pass it;
    //    - shortening cut the end point beyond zFarMax (the usual receiver, below its
    //      occluders) of a region holding occluders: the end lies deeper than zNearMin, so
    //      within the Eq 3.3 region (every crossing below the last iteration's occluder
    //      depth, which is at most zNearMin), whose far layer is at most zFarMax: it cannot
    //      be inside, and the inside test is not needed at all.
    //    Elsewhere (the end cut above zNearMin: a receiver within the bias of an occluder,
    //    whose end texel may lie outside the region) the inside test decides first, so its
    //    ray's region fetch is counted though the inside test then ends the ray.
    uint fetchesBefore = gFetches;
    bool endKept = sStart <= sEndPoint && sEndPoint <= sEnd;
    bool insideDecidesFirst = !endKept && !(sEnd < sEndPoint && zBounds.y >= zBounds.x);
    bool regionEmpty = sStart > sEnd || (trace.switches.z != 0 && regionIsEmpty(ray, sStart, sEnd, layers));
    bool inside = trace.switches.y != 0 && (insideDecidesFirst || (endKept && !regionEmpty)) &&
                  endPointInside(ray, sEndPoint, wsEnd, layers, counts);
    gEarlyOutFetches += gFetches - fetchesBefore;
    if (inside) continue;
    if (regionEmpty) {
      counts.region += 1u;
      ++unblocked;
      recordStep(-1, STEP_EARLY_REGION, 0, ivec4(-1), vec4(0.0), vec4(sStart, sEnd, rayPoint(ray, sEnd)));
      continue;
    }
    // 5. The search.
    counts.searched += 1u;
    bool blocked = search == SEARCH_HIERARCHICAL
                       ? searchHierarchical(ray, sStart, sEnd, layers)
                       : searchLinear(ray, sStart, sEnd, layers, search == SEARCH_LINEAR_BINARY);
    if (!blocked) ++unblocked;
  }
  return float(unblocked) / float(rayCount);
}

void addTotals(RayCounts counts, uint rays) {
  atomicAdd(totals[TOTAL_RAYS], rays);
  atomicAdd(totals[TOTAL_RAYS_SEARCHED], counts.searched);
  atomicAdd(totals[TOTAL_FETCHES], gFetches);
  atomicAdd(totals[TOTAL_EARLY_OUT_FETCHES], gEarlyOutFetches);
  atomicAdd(totals[TOTAL_ITERATIONS], gIterations);
  atomicAdd(totals[TOTAL_EARLY_BACKFACE], counts.backface);
  atomicAdd(totals[TOTAL_EARLY_INSIDE], counts.inside);
  atomicAdd(totals[TOTAL_EARLY_REGION], counts.region);
}

// Rays from a receiver to points on the light, in the light's texel space (thesis §3,
// §3.3). A ray runs from A (the light sample: on the near plane, lsDepth 0) to B (the
// receiver, moved towards the light by the bias). Texel space is uv * map size; texel
// (i, j) covers [i, i+1) x [j, j+1). Along the projected segment P(s) = A + s (B - A),
// s in [0, 1], perspective makes 1/z affine in s, so a ray's lsDepth is monotone in s and
// is computed exactly at any s (no world/texture stepping drift, cf. §3.5's remark).
#include "frame.glsl"
#include "nbuffer.glsl"
#include "minmax.glsl"
#include "trace_layout.h"

// The trace's parameters (trace_layout.h), read where they are used.
layout(std140, binding = TRACE_PARAMS_BINDING) uniform TraceBlock { TraceParams trace; };
layout(std430, binding = TRACE_RECORDS_BINDING) buffer TraceRecords { uvec4 recordHeader; TraceStep records[]; };
layout(std430, binding = TRACE_TOTALS_BINDING) buffer TraceTotals { uint totals[TOTAL_COUNT]; };

layout(binding = TRACE_NEAR_UNIT) uniform sampler2D nearLayer;
// The light's depth layers (§3.3) and the hierarchy over them (§3.5), all read with
// texelFetch: every read is of one whole texel.
layout(binding = TRACE_FAR_UNIT) uniform sampler2D farLayer;
layout(binding = TRACE_LEVELS_UNIT) uniform sampler2DArray nbufferLevels;
layout(binding = TRACE_MINMAX_UNIT) uniform sampler2D minmaxLevels;  // level n >= 1: mip n - 1

struct Ray {
  vec2 a, d;            // texel space start and direction (B - A)
  float invZa, invZb;   // 1 / linear depth at A and B
  vec3 wsA, wsB;        // world end points (three layers need world points)
};

// Statistics and recording state of the current invocation: texel fetches (all of them, and
// those of the early-out tests of §3.7 among them; the rest are the searches'), search
// iterations.
uint gFetches = 0u, gEarlyOutFetches = 0u, gIterations = 0u;
bool gRecording = false;
int gRayIndex = 0;

// Specializations. The pipeline compiles one trace program per hierarchy, search and
// layer count (TRACE_HIERARCHY, TRACE_SEARCH, TRACE_LAYERS), each holding the one path of
// the thesis's algorithm that the run takes (§3.2-3.5), so a student reads, and a driver
// compiles, no code a ray never runs. Undefined (the test shaders): chosen at run time from
// the parameter block, which the pipeline fills with the same values.
#ifdef TRACE_HIERARCHY
#define traceHierarchy() TRACE_HIERARCHY
#else
#define traceHierarchy() trace.limits.z
#endif
#ifdef TRACE_SEARCH
#define traceSearch() TRACE_SEARCH
#else
#define traceSearch() trace.config.z
#endif
#ifdef TRACE_LAYERS
#define traceLayers() TRACE_LAYERS
#else
#define traceLayers() trace.config.w
#endif

// TRACE_RECORDING 0 compiles the step records out. The deferred pass over many pixels uses
// that variant and traces the recorded pixel again, alone, with recording on (the forward
// pass cannot trace one pixel alone: with a recorded pixel it runs the recording variant
// throughout), so the pass that draws the image carries no code for the trace window.
// Undefined: on.
#ifndef TRACE_RECORDING
#define TRACE_RECORDING 1
#endif

void recordStep(int level, int decision, int iteration, ivec4 window, vec4 depths,
                vec4 stepping) {
#if TRACE_RECORDING
  if (!gRecording) return;
  uint slot = atomicAdd(recordHeader.x, 1u);
  if (slot >= uint(trace.record.z)) return;
  records[slot].header = ivec4(gRayIndex, level, decision, iteration);
  records[slot].window = window;
  records[slot].depths = depths;
  records[slot].stepping = stepping;
#endif
}

vec2 mapSize() { return vec2(light.mapSize.xy); }

vec2 rayPoint(Ray ray, float s) { return ray.a + s * ray.d; }
float rayLsDepth(Ray ray, float s) { return zToLsDepth(1.0 / mix(ray.invZa, ray.invZb, s)); }
// The s at which the ray reaches lsDepth (inverse of rayLsDepth; unclamped).
float raySAtLsDepth(Ray ray, float lsDepth) {
  float invZ = 1.0 / lsDepthToZ(lsDepth);
  return (invZ - ray.invZa) / (ray.invZb - ray.invZa);
}
// World point at s: z is affine in the world parameter t, so t = (z(s) - zA) / (zB - zA).
vec3 rayWorldPoint(Ray ray, float s) {
  float zA = 1.0 / ray.invZa, zB = 1.0 / ray.invZb;
  float t = (1.0 / mix(ray.invZa, ray.invZb, s) - zA) / (zB - zA);
  return mix(ray.wsA, ray.wsB, t);
}

Ray makeRay(vec3 wsLightSample, vec3 wsEnd) {
  vec3 a = lightMapCoords(wsLightSample), b = lightMapCoords(wsEnd);
  Ray ray;
  ray.a = a.xy * mapSize();
  ray.d = b.xy * mapSize() - ray.a;
  ray.invZa = 1.0 / a.z;
  ray.invZb = 1.0 / b.z;
  ray.wsA = wsLightSample;
  ray.wsB = wsEnd;
  return ray;
}

// Clips [s0, s1] to the part of the segment inside the map [0, W] x [0, H] (slab test).
// Returns false when nothing is left: outside the map there are no occluders.
bool clipToMap(Ray ray, inout float s0, inout float s1) {
  vec2 size = mapSize();
  for (int axis = 0; axis < 2; ++axis) {
    if (abs(ray.d[axis]) < 1e-12) {
      if (ray.a[axis] < 0.0 || ray.a[axis] > size[axis]) return false;
      continue;
    }
    float t0 = (0.0 - ray.a[axis]) / ray.d[axis], t1 = (size[axis] - ray.a[axis]) / ray.d[axis];
    s0 = max(s0, min(t0, t1));
    s1 = min(s1, max(t0, t1));
  }
  return s0 <= s1;
}

ivec2 texelAt(vec2 p) { return clamp(ivec2(floor(p)), ivec2(0), ivec2(light.mapSize.xy) - 1); }

vec2 fetchLayers(ivec2 texel) {
  gFetches += 2u;
  return vec2(texelFetch(nearLayer, texel, 0).r, texelFetch(farLayer, texel, 0).r);
}
// One texel of the hierarchy (traceHierarchy()): an N-buffer texel (nbuffer.glsl), or a
// min-max mipmap texel in level coordinates (minmax.glsl; level 0 is the layers).
vec4 hierarchyTexel(ivec2 texel, int level) {
  if (traceHierarchy() != HIERARCHY_MINMAX) return texelFetch(nbufferLevels, ivec3(texel, level), 0);
  if (level > 0)
    return texelFetch(minmaxLevels, texel, level - 1);
  float nearDepth = texelFetch(nearLayer, texel, 0).r;
  return vec4(nearDepth, nearDepth, texelFetch(farLayer, texel, 0).r, 0.0);
}
vec4 fetchHierarchy(ivec2 texel, int level) {  // counted: level 0 of the min-max mipmap is 2
  gFetches += traceHierarchy() == HIERARCHY_MINMAX && level == 0 ? 2u : 1u;
  return hierarchyTexel(texel, level);
}

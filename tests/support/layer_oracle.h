// Independent CPU oracle for shadow rays traced through the light's depth layers (thesis §2.2:
// "a completely accurate intersection would require taking a sample each time the ray
// crosses a texel boundary"; §3.3 two layers; §3.4 third layer = the eye's depth).
// It walks every texel a ray crosses (Amanatides & Woo 1987) and decides each texel exactly;
// it shares no code or logic with the shaders and is what the `trace` stage tests compare to.
//
// THE RAY MODEL
// - Texel space: texel (i, j) covers [i, i+1) x [j, j+1); uv = texel / (W, H); layers are
//   W x H floats in GL order (index y * W + x, y = 0 at v = 0) holding lsDepth in [0, 1]
//   (linear light depth, shaders/shared/frame_block.h). Texels outside the map are empty.
// - A ray is the texel-space segment P(s) = A + s (B - A), s in [0, 1], from the light sample A
//   to the biased receiver end B, with linear depths zA, zB (> 0). Perspective makes 1/z
//   affine in s: 1/z(s) = (1 - s)/zA + s/zB, lsDepth(s) = (z(s) - zNear) / (zFar - zNear).
//   lsDepth is monotone in s, so over any s-interval its range is spanned by the two ends.
// - The texel at s is exactly floor(P(s)) (half-open texels). So each visited texel owns a
//   half-open s-interval: [s0, s1) along +x/+y, (s0, s1] along -x/-y, and a segment crossing
//   a corner with mixed signs (+x, -y) owns the corner point alone in a third texel: a span
//   [s*, s*]. An end point exactly on a boundary lies in the texel floor() gives (B = (5, y)
//   is in column 5 as a single point). Every TexelSpan records which ends it owns.
// - Two layers (§3.3): occluded iff some s has near[T] <= lsDepth(s) <= far[T], T = floor(P(s))
//   in the map. near > far (cleared near = 1 / far = 0, or a "both" texel) holds nothing.
// - One layer (§3.2): occluded iff some s has lsDepth(s) >= near[T] (T in the map).
// - Three layers (§3.4): a point between near and far occludes only if the eye cannot see it.
//   Not exact: within each texel, the exact piece of the ray inside [near, far] (see
//   occludedPieces) is sampled at its two ends and `interiorSamples` evenly spaced interior
//   points (a continuous answer would need the eye buffer's geometry). So a sheet crossing
//   (a one-point piece) is still tested, and with an eye that sees nothing the answer is
//   exactly the two-layer one.
//
// FLOATING POINT: inputs are float, all work is double. Boundary crossings are
// s_k = (k - A) / (B - A) per axis, always by that one expression, so equal crossings (corner
// hits, end points on boundaries) compare equal exactly whenever k - A and B - A are exact in
// double (always for coordinates of moderate size, e.g. on a 2^-20 grid below 2^20);
// otherwise crossings within ~1e-16 of each other count as simultaneous. lsDepth at s = 0 and
// s = 1 is computed from zA, zB directly (no 1/(1/z) round trip), so an end point's depth is
// exactly (z - zNear) / (zFar - zNear) in double.
#pragma once
#include <functional>
#include <glm/glm.hpp>
#include <limits>
#include <vector>

#include "scene/light_frame.h"
#include "scene/scene.h"

struct LayerMaps {
  int width = 0, height = 0;
  std::vector<float> nearLayer, farLayer;  // lsDepth, index y * width + x
  bool contains(glm::ivec2 t) const { return t.x >= 0 && t.y >= 0 && t.x < width && t.y < height; }
  float nearAt(glm::ivec2 t) const { return nearLayer[size_t(t.y) * width + t.x]; }
  float farAt(glm::ivec2 t) const { return farLayer[size_t(t.y) * width + t.x]; }
};
// All texels empty: near 1, far 0 (the cleared state, thesis §3.3).
LayerMaps emptyLayers(int width, int height);

struct OracleRay {
  glm::vec2 texelA, texelB;  // texel-space end points (light sample, biased receiver)
  float zA, zB;              // linear depth along the light axis at A and B, both > 0
};

// lsDepth along a ray (the model above); `at` is monotone in s.
struct RayDepth {
  double zA, zB, zNear, zFar;
  RayDepth(const OracleRay& ray, double zNear, double zFar);
  double zAt(double s) const;
  double at(double s) const { return (zAt(s) - zNear) / (zFar - zNear); }
  // The s where lsDepth(s) == lsDepth (extrapolated beyond [0, 1] if need be); NaN when the
  // depth is constant along the ray.
  double sAtDepth(double lsDepth) const;
};

// One texel's part of the ray. s0 <= s1; owns0/owns1 say whether the texel owns the ends
// (floor semantics); s0 == s1 only for a point span (both ends owned).
struct TexelSpan {
  glm::ivec2 texel;
  double s0, s1;
  bool owns0, owns1;
};

// Every texel T with lo <= T < hi that the ray visits, in order of s, with its s-interval.
// The segment is first clipped to the box [lo, hi] (entering and leaving through the same
// crossing expressions), so a segment mostly outside costs only its inside part.
std::vector<TexelSpan> texelSpans(const OracleRay& ray, glm::ivec2 lo, glm::ivec2 hi);
// Texel-space point at s (double).
glm::dvec2 rayPoint(const OracleRay& ray, double s);

struct OracleHit {
  bool occluded = false;
  // First hit (occluded only): the infimum s of the occluded set, its texel, and where the
  // occluded s-interval inside that texel ends (s == sFirstHitEnd: it is hit at one point).
  double s = 1, sFirstHitEnd = 1;
  glm::ivec2 texel{-1, -1};
  int texelsVisited = 0;  // in-map texels walked up to and including the hit texel (all if clear)
  int texelsOnRay = 0;    // all in-map texels the ray crosses
  // Robustness (for comparing with sampled or float traces):
  // occluded: the longest occluded s-interval within a single texel (0: hit at points only);
  double hitLength = 0;
  // clear: the smallest lsDepth gap between the ray and [near, far] (one layer: near) over the
  // texels that hold something (infinity if none; 0 if the ray touches a layer at an end the
  // texel does not own).
  double clearance = std::numeric_limits<double>::infinity();
};

OracleHit traceTwoLayers(const LayerMaps& maps, const OracleRay& ray, float zNear, float zFar);
OracleHit traceOneLayer(const LayerMaps& maps, const OracleRay& ray, float zNear, float zFar);

// Two layers, every piece: for each visited texel where the ray meets [near, far], the s-interval
// inside it where lsDepth is in [near, far] (the closure; s0 == s1 when the ray touches a
// sheet near == far or a corner point). spanIndex counts in-map texels along the ray from 0.
struct OccludedPiece {
  glm::ivec2 texel;
  int spanIndex;
  double s0, s1;
};
std::vector<OccludedPiece> occludedPieces(const LayerMaps& maps, const OracleRay& ray, float zNear,
                                          float zFar);

// Error-tolerant verdict, for comparing an exact traversal computed with small errors: its ray
// points off by up to `texels` (max norm, < 0.5) and its ray depth, still continuous and
// monotone in s, off by up to `lsDepth`. Occluded: some texel, shrunk by `texels`, holds a
// piece of the ray whose depth range [dMin, dMax] satisfies dMin + lsDepth <= far and
// dMax - lsDepth >= near (every such implementation sees a hit; a sheet near == far crossed
// with margin counts). Clear: no texel grown by `texels` holds a piece with
// dMin - lsDepth <= far and dMax + lsDepth >= near. Otherwise Ambiguous. Closed boxes.
enum class Verdict { Clear, Occluded, Ambiguous };
struct Tolerance {
  double texels = 1e-3, lsDepth = 1e-5;
};
Verdict classifyTwoLayers(const LayerMaps& maps, const OracleRay& ray, float zNear, float zFar,
                          Tolerance tolerance);
Verdict classifyOneLayer(const LayerMaps& maps, const OracleRay& ray, float zNear, float zFar,
                         Tolerance tolerance);

// ---- Light space (layer_oracle_light.cpp) ----
// Map position (texels, z = linear depth) of a world point and back; computed in double from
// lightViewFromWorld and the half-fov tangents (the same frustum as lightClipFromWorld).
glm::dvec3 lightMapFromWorld(const LightFrame& frame, int mapW, int mapH, const glm::dvec3& ws);
glm::dvec3 worldFromLightMap(const LightFrame& frame, int mapW, int mapH, glm::dvec2 texel,
                             double z);
// World point of the light sample (u, v) in [0, 1]^2:
// center + (2u - 1) right width/2 + (2v - 1) up height/2 (LightFrame's right/up).
glm::dvec3 lightSampleWorld(const LightFrame& frame, const AreaLight& light, glm::vec2 sample01);
// The ray from the light sample to the receiver. A = sample01 * (W, H) exactly, zA = zNear
// (the light rectangle is the near plane's cross-section, Eq 3.1). Bias: the receiver end
// moves towards the light sample by biasWorld world units, at most the whole way (then B = A).
OracleRay makeRay(const LightFrame& frame, const AreaLight& light, int mapW, int mapH,
                  glm::vec2 sample01, const glm::vec3& wsReceiver, float biasWorld);

// Third layer (§3.4). visibleFromEye gets the world point of a ray sample inside [near, far].
using EyeVisibility = std::function<bool(const glm::dvec3& wsPoint)>;
OracleHit traceThreeLayers(const LayerMaps& maps, const OracleRay& ray, const LightFrame& frame,
                           const EyeVisibility& visibleFromEye, int interiorSamples = 3);

// Fraction of an n x n grid of light samples (cell centers) whose ray is not occluded;
// layers = 1 or 2.
float denseVisibility(const LayerMaps& maps, const LightFrame& frame, const AreaLight& light,
                      const glm::vec3& wsReceiver, float biasWorld, int n, int layers);
// Same with any tracer (e.g. traceThreeLayers bound to a callback), for a mapW x mapH map.
float denseVisibility(const LightFrame& frame, const AreaLight& light, int mapW, int mapH,
                      const glm::vec3& wsReceiver, float biasWorld, int n,
                      const std::function<OracleHit(const OracleRay&)>& trace);

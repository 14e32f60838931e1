// Exact texel-by-texel traversal and the one- and two-layer decisions (see layer_oracle.h).
#include "support/layer_oracle.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A boundary crossing: where along the ray, and whether the texel changes at s (phase 0: a
// +x/+y step, the new texel owns s) or just after s (phase 1: a -x/-y step, the old texel
// owns s). Ordered by (s, phase), so at a shared s the positive steps come first.
struct Crossing {
  double s;
  int phase;
  bool operator==(const Crossing&) const = default;
  bool operator<(const Crossing& o) const { return s < o.s || (s == o.s && phase < o.phase); }
};

// One coordinate of the segment. crossing(k) is THE expression for where it meets the line
// x = k; everything (clipping, start index, steps) uses it so ties stay exact.
struct Axis {
  double a, d;  // start and B - A (exact in double for float inputs of moderate size)
  double crossing(int k) const { return (double(k) - a) / d; }
  // floor(coordinate at s), consistent with crossing(): for d > 0 the largest k with
  // crossing(k) <= s, for d < 0 the largest k with crossing(k) >= s.
  int indexAt(double s) const {
    if (d == 0) return int(std::floor(a));
    int k = int(std::floor(a + s * d));
    if (d > 0) {
      while (crossing(k + 1) <= s) ++k;
      while (crossing(k) > s) --k;
    } else {
      while (crossing(k + 1) >= s) ++k;
      while (crossing(k) < s) --k;
    }
    return k;
  }
  Crossing next(int index) const {
    if (d > 0) return {crossing(index + 1), 0};
    if (d < 0) return {crossing(index), 1};
    return {kInfinity, 0};
  }
  int step() const { return d > 0 ? 1 : -1; }
};

// lsDepth range of a span: ends sorted, with ownership; `point` when it is a single value.
struct DepthRange {
  double lo, hi;
  bool ownsLo, ownsHi, point;
};
DepthRange depthRange(const RayDepth& depth, const TexelSpan& span) {
  const double d0 = depth.at(span.s0), d1 = depth.at(span.s1);
  if (d0 == d1) return {d0, d1, true, true, true};  // constant depth or a point span
  if (d0 < d1) return {d0, d1, span.owns0, span.owns1, false};
  return {d1, d0, span.owns1, span.owns0, false};
}
// Does the span's depth set meet the closed solid interval [lo, hi]? (hi = inf: one layer.)
bool meets(const DepthRange& r, double lo, double hi) {
  if (lo > hi) return false;
  if (r.point) return lo <= r.lo && r.lo <= hi;
  return (r.lo < hi || (r.lo == hi && r.ownsLo)) && (r.hi > lo || (r.hi == lo && r.ownsHi));
}
double gap(const DepthRange& r, double lo, double hi) {
  if (r.hi <= lo) return lo - r.hi;
  if (r.lo >= hi) return r.lo - hi;
  return 0;
}
// The s-interval inside the span where lsDepth is in [lo, hi] (called when meets()).
void hitInterval(const RayDepth& depth, const TexelSpan& span, double lo, double hi,
                 double& sBegin, double& sEnd) {
  const double sLo = depth.sAtDepth(lo), sHi = depth.sAtDepth(hi);
  if (std::isnan(sLo) || std::isnan(sHi)) {  // constant depth: the whole span
    sBegin = span.s0, sEnd = span.s1;
    return;
  }
  const double a = std::min(sLo, sHi), b = std::max(sLo, sHi);
  sBegin = std::clamp(a, span.s0, span.s1);
  sEnd = std::clamp(b, span.s0, span.s1);
  if (sBegin > sEnd) sBegin = sEnd = (a > span.s1 ? span.s1 : span.s0);  // rounding only
}

// One and two layers differ only in the solid interval of a texel.
template <class Solid>
OracleHit trace(const LayerMaps& maps, const OracleRay& ray, float zNear, float zFar,
                Solid solid, std::vector<OccludedPiece>* pieces = nullptr) {
  const RayDepth depth(ray, zNear, zFar);
  const std::vector<TexelSpan> spans = texelSpans(ray, {0, 0}, {maps.width, maps.height});
  OracleHit hit;
  hit.texelsOnRay = int(spans.size());
  for (size_t index = 0; index < spans.size(); ++index) {
    const TexelSpan& span = spans[index];
    if (!hit.occluded) ++hit.texelsVisited;
    double lo, hi;
    solid(span.texel, lo, hi);
    if (lo > hi) continue;  // empty or "both" texel (§3.3): nothing there
    const DepthRange range = depthRange(depth, span);
    if (!meets(range, lo, hi)) {
      if (!hit.occluded) hit.clearance = std::min(hit.clearance, gap(range, lo, hi));
      continue;
    }
    double sBegin, sEnd;
    hitInterval(depth, span, lo, hi, sBegin, sEnd);
    if (pieces) pieces->push_back({span.texel, int(index), sBegin, sEnd});
    if (!hit.occluded) {
      hit.occluded = true;
      hit.s = sBegin, hit.sFirstHitEnd = sEnd, hit.texel = span.texel;
      hit.clearance = 0;
    }
    hit.hitLength = std::max(hit.hitLength, sEnd - sBegin);
  }
  return hit;
}

// The closed s-interval of the segment inside the closed box [lo, hi] (texel space), or false.
bool clipToBox(const OracleRay& ray, glm::dvec2 lo, glm::dvec2 hi, double& s0, double& s1) {
  s0 = 0, s1 = 1;
  for (int axis = 0; axis < 2; ++axis) {
    const double a = ray.texelA[axis], d = double(ray.texelB[axis]) - a;
    if (d == 0) {
      if (a < lo[axis] || a > hi[axis]) return false;
      continue;
    }
    const double t0 = (lo[axis] - a) / d, t1 = (hi[axis] - a) / d;
    s0 = std::max(s0, std::min(t0, t1));
    s1 = std::min(s1, std::max(t0, t1));
  }
  return s0 <= s1;
}

template <class Solid>
Verdict classify(const LayerMaps& maps, const OracleRay& ray, float zNear, float zFar,
                 Tolerance tolerance, Solid solid) {
  const double e = std::clamp(tolerance.texels, 0.0, 0.49), dd = std::max(tolerance.lsDepth, 0.0);
  const RayDepth depth(ray, zNear, zFar);
  // A texel whose grown box meets the segment neighbours a texel the segment visits (e < 1);
  // walk one texel beyond the map so the map's border texels are found from outside too.
  std::vector<int> candidates;
  for (const TexelSpan& span : texelSpans(ray, {-1, -1}, {maps.width + 1, maps.height + 1}))
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const glm::ivec2 t = span.texel + glm::ivec2(dx, dy);
        if (maps.contains(t)) candidates.push_back(t.y * maps.width + t.x);
      }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());

  // Inside the box the ray's depth runs over [dMin, dMax]; moved by up to `shift` at each end
  // (continuously, monotone), does it still meet [lo, hi] (shift = +dd: always; shift = -dd:
  // possibly)? A crossing of a sheet (lo == hi) deep enough is thus a sure hit.
  auto reaches = [&](glm::dvec2 boxLo, glm::dvec2 boxHi, double lo, double hi, double shift) {
    double s0, s1;
    if (!clipToBox(ray, boxLo, boxHi, s0, s1)) return false;
    const double d0 = depth.at(s0), d1 = depth.at(s1);
    return std::min(d0, d1) + shift <= hi && std::max(d0, d1) - shift >= lo;
  };
  bool possible = false;
  for (int index : candidates) {
    const glm::ivec2 t(index % maps.width, index / maps.width);
    double lo, hi;
    solid(t, lo, hi);
    if (lo > hi) continue;
    const glm::dvec2 corner(t);
    if (reaches(corner + e, corner + 1.0 - e, lo, hi, dd)) return Verdict::Occluded;
    possible = possible || reaches(corner - e, corner + 1.0 + e, lo, hi, -dd);
  }
  return possible ? Verdict::Ambiguous : Verdict::Clear;
}

auto twoLayerSolid(const LayerMaps& maps) {
  return [&maps](glm::ivec2 t, double& lo, double& hi) { lo = maps.nearAt(t), hi = maps.farAt(t); };
}
auto oneLayerSolid(const LayerMaps& maps) {
  return [&maps](glm::ivec2 t, double& lo, double& hi) { lo = maps.nearAt(t), hi = kInfinity; };
}
}  // namespace

LayerMaps emptyLayers(int width, int height) {
  LayerMaps maps;
  maps.width = width, maps.height = height;
  maps.nearLayer.assign(size_t(width) * height, 1.0f);
  maps.farLayer.assign(size_t(width) * height, 0.0f);
  return maps;
}

RayDepth::RayDepth(const OracleRay& ray, double zNear, double zFar)
    : zA(ray.zA), zB(ray.zB), zNear(zNear), zFar(zFar) {
  if (!(zA > 0) || !(zB > 0) || !(zFar > zNear))
    throw std::invalid_argument("layer oracle: ray depths must be > 0 and zFar > zNear");
}
double RayDepth::zAt(double s) const {
  if (s == 0) return zA;
  if (s == 1) return zB;
  return 1.0 / ((1.0 - s) / zA + s / zB);  // 1/z is affine in s (perspective)
}
double RayDepth::sAtDepth(double lsDepth) const {
  if (zA == zB) return std::nan("");
  const double z = zNear + lsDepth * (zFar - zNear);
  const double w = z > 0 ? 1.0 / z : kInfinity;
  return (w - 1.0 / zA) / (1.0 / zB - 1.0 / zA);
}

glm::dvec2 rayPoint(const OracleRay& ray, double s) {
  if (s == 1) return glm::dvec2(ray.texelB);
  const glm::dvec2 a(ray.texelA);
  return a + s * (glm::dvec2(ray.texelB) - a);
}

std::vector<TexelSpan> texelSpans(const OracleRay& ray, glm::ivec2 lo, glm::ivec2 hi) {
  std::vector<TexelSpan> spans;
  if (!std::isfinite(ray.texelA.x) || !std::isfinite(ray.texelA.y) ||
      !std::isfinite(ray.texelB.x) || !std::isfinite(ray.texelB.y))
    throw std::invalid_argument("layer oracle: non-finite ray");
  if (lo.x >= hi.x || lo.y >= hi.y) return spans;
  const Axis axes[2] = {{ray.texelA.x, double(ray.texelB.x) - ray.texelA.x},
                        {ray.texelA.y, double(ray.texelB.y) - ray.texelA.y}};
  // Clip to the box [lo, hi]: enter at the last entering crossing, leave at the first leaving
  // one (a constant coordinate is inside iff floor() of it is in [lo, hi)).
  double sIn = 0, sOut = 1;
  for (int i = 0; i < 2; ++i) {
    const Axis& axis = axes[i];
    if (axis.d == 0) {
      if (axis.a < lo[i] || axis.a >= hi[i]) return spans;
    } else {
      sIn = std::max(sIn, axis.crossing(axis.d > 0 ? lo[i] : hi[i]));
      sOut = std::min(sOut, axis.crossing(axis.d > 0 ? hi[i] : lo[i]));
    }
  }
  if (sIn > sOut) return spans;

  glm::ivec2 texel(axes[0].indexAt(sIn), axes[1].indexAt(sIn));
  double sEnter = sIn;
  bool ownsEnter = true;  // the start texel owns its first point by construction of indexAt
  auto emit = [&](double sExit, bool ownsExit) {
    const bool inside = texel.x >= lo.x && texel.y >= lo.y && texel.x < hi.x && texel.y < hi.y;
    const bool nonEmpty = sEnter < sExit || (ownsEnter && ownsExit);
    if (inside && nonEmpty) spans.push_back({texel, sEnter, sExit, ownsEnter, ownsExit});
  };
  const int maxSteps = 2 * ((hi.x - lo.x) + (hi.y - lo.y)) + 8;
  for (int step = 0;; ++step) {
    if (step > maxSteps) throw std::logic_error("layer oracle: traversal did not end");
    const Crossing cx = axes[0].next(texel.x), cy = axes[1].next(texel.y);
    const Crossing c = std::min(cx, cy);
    // A positive step at sOut still happens (the new texel owns sOut); a negative one does not.
    if (!(c.s < sOut || (c.s == sOut && c.phase == 0))) {
      emit(sOut, true);
      break;
    }
    emit(c.s, c.phase == 1);
    if (cx == c) texel.x += axes[0].step();
    if (cy == c) texel.y += axes[1].step();
    sEnter = c.s, ownsEnter = c.phase == 0;
  }
  return spans;
}

OracleHit traceTwoLayers(const LayerMaps& maps, const OracleRay& ray, float zNear, float zFar) {
  return trace(maps, ray, zNear, zFar, twoLayerSolid(maps));
}
std::vector<OccludedPiece> occludedPieces(const LayerMaps& maps, const OracleRay& ray, float zNear,
                                          float zFar) {
  std::vector<OccludedPiece> pieces;
  trace(maps, ray, zNear, zFar, twoLayerSolid(maps), &pieces);
  return pieces;
}
OracleHit traceOneLayer(const LayerMaps& maps, const OracleRay& ray, float zNear, float zFar) {
  return trace(maps, ray, zNear, zFar, oneLayerSolid(maps));
}
Verdict classifyTwoLayers(const LayerMaps& maps, const OracleRay& ray, float zNear, float zFar,
                          Tolerance tolerance) {
  return classify(maps, ray, zNear, zFar, tolerance, twoLayerSolid(maps));
}
Verdict classifyOneLayer(const LayerMaps& maps, const OracleRay& ray, float zNear, float zFar,
                         Tolerance tolerance) {
  return classify(maps, ray, zNear, zFar, tolerance, oneLayerSolid(maps));
}

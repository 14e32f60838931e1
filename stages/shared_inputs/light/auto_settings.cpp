#include "shared_inputs/light/auto_settings.h"

#include "gl/renderer_calibration.h"
#include "shared_inputs/light/auto_frustum.h"
#include "shared_inputs/light/occluder_image.h"
#include "shared_inputs/light/scene_rays.h"
#include "shared_inputs/weighted_percentile.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <memory>
#include <mutex>
#include <thread>

namespace {

double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0;
  const size_t k = std::min(values.size() - 1, size_t(fraction * double(values.size())));
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
  return values[k];
}

// Work to build a map of this size, in texel-levels: the N-buffer's log2(resolution) + 1
// levels and the light layers, about 2 levels' worth (measured: 2.1 at 2048, 2.7 at 512).
double mapBuildWork(int resolution) {
  return double(resolution) * double(resolution) * (std::log2(double(resolution)) + 3.0);
}

std::string format(const char* pattern, double a, double b = 0, double c = 0) {
  char text[256];
  std::snprintf(text, sizeof text, pattern, a, b, c);
  return text;
}

// ---- Layers: separate occluders on one light ray (step 5) ----
// Two layers bound everything between the nearest and the farthest occluder surface on a
// light ray as solid (thesis §3.3, Fig 3.4: "gaps may exist between multiple occluders");
// the third, the eye's depth (§3.4), frees the part of those gaps the eye sees. Counting
// surfaces alone (more than two on a ray: step 5's first rule) misses the simplest such gap:
// two sheets (plates) one above the other are two surfaces, as one box is, but the space
// between them is free, and two layers fill it (a too-dark band where rays pass between
// the plates). Here the surfaces a probe's light ray crosses are paired into solids by their
// facing: on one object, a surface the ray enters through and the next it leaves through
// (geometric normals facing opposite ways along the ray: any closed mesh, whichever its
// winding) bound one solid; a surface with no such partner is a sheet, of zero thickness.
// The free space on the ray between its first and last occluder surface, outside every
// solid, is what two layers fill.

// One occluder surface on a light ray: where, on which object, and which way it faces.
struct RaySurface {
  float t;
  unsigned object;
  bool facesAlong;  // geometric normal along the ray (the ray leaves through it, if closed)
};

// The occluder surfaces along origin + t direction, nearest first, up to the first
// receiver-only surface (nothing beyond it shadows what the camera sees there) or 8.
std::vector<RaySurface> occluderSurfacesAlong(const SceneRays& rays, const glm::vec3& origin,
                                              const glm::vec3& direction) {
  std::vector<RaySurface> surfaces;
  float tFrom = 0;
  for (int k = 0; k < 8; ++k) {
    unsigned g = 0;
    glm::vec3 normal(0);
    const float t = rays.hit(origin, direction, tFrom, g, &normal);
    if (g == RTC_INVALID_GEOMETRY_ID || !rays.occluder[g]) break;
    surfaces.push_back({t, g, glm::dot(normal, direction) > 0.0f});
    tFrom = t + 1e-4f * std::max(1.0f, t);
  }
  return surfaces;
}

// The longest free stretch of the ray between its first and last occluder surface (world
// units along the ray; 0 when the surfaces bound one solid, or there are fewer than two),
// and the ray parameter at its middle.
struct FreeGap {
  float length = 0, tMiddle = 0;
};
FreeGap longestFreeGap(const std::vector<RaySurface>& surfaces) {
  // Solids: per object, a surface and the next one of the same object facing the other way.
  std::vector<std::pair<float, float>> solids;
  std::vector<bool> paired(surfaces.size(), false);
  for (size_t i = 0; i < surfaces.size(); ++i) {
    if (paired[i]) continue;
    for (size_t j = i + 1; j < surfaces.size(); ++j) {
      if (paired[j] || surfaces[j].object != surfaces[i].object) continue;
      if (surfaces[j].facesAlong != surfaces[i].facesAlong) {
        solids.emplace_back(surfaces[i].t, surfaces[j].t);
        paired[i] = paired[j] = true;
      }
      break;  // the object's next surface: paired, or this one is a sheet
    }
  }
  FreeGap gap;
  for (size_t i = 0; i + 1 < surfaces.size(); ++i) {
    const float from = surfaces[i].t, to = surfaces[i + 1].t;
    const float middle = 0.5f * (from + to);
    bool inside = false;
    for (const auto& [enter, leave] : solids) inside = inside || (enter <= middle && middle <= leave);
    if (!inside && to - from > gap.length) gap = {to - from, middle};
  }
  return gap;
}

// For one probe (a point q on an occluder's triangle, `inward` a point inside that triangle):
// the free gap on the light's ray from its centre through q, in texels per unit map
// resolution at the gap's depth (times the map size: texels). The ray is aimed a little
// inside the triangle, so that it meets the probe's own occluder rather than grazing its edge.
double freeGapTexelsPerResolution(const SceneRays& rays, const AreaLight& area,
                                  const LightFrame& light, const glm::vec3& q,
                                  const glm::vec3& inward) {
  const glm::vec3 aim = q + 1e-3f * (inward - q);
  const glm::vec3 direction = glm::normalize(aim - area.center);
  const FreeGap gap = longestFreeGap(occluderSurfacesAlong(rays, area.center, direction));
  if (gap.length <= 0) return 0;
  const glm::vec3 middle = area.center + gap.tMiddle * direction;
  const float z = glm::dot(middle - light.wsProjectionPoint, light.forward);
  const float tanHalfFov = std::max(light.tanHalfFovX, light.tanHalfFovY);
  return z > 0 ? double(gap.length) / (2.0 * double(z) * double(tanHalfFov)) : 0.0;
}

// Step 5: three layers where one light ray meets more than two occluder surfaces (the rule
// before), or where at least kSeparateFraction of the probes in view have a free gap of at
// least kGapTexels texels of the chosen map between two occluders (a gap thinner than that
// is within what the layers resolve, and the Eq 3.2 bias passes it).
inline constexpr double kSeparateFraction = 0.05, kGapTexels = 2.0;
void chooseLayers(const std::vector<double>& gapsPerResolution, AutoSettings& out) {
  out.separateOccluderProbes = 0;
  double widestGap = 0;
  for (double gap : gapsPerResolution) {
    if (gap * out.resolution >= kGapTexels) ++out.separateOccluderProbes;
    widestGap = std::max(widestGap, gap * out.resolution);
  }
  const double fraction =
      gapsPerResolution.empty() ? 0.0 : double(out.separateOccluderProbes) / double(gapsPerResolution.size());
  if (out.depthComplexity > 2) {
    out.layers = 3;
    out.reasons.push_back(format("layers %.0f: at most %.0f occluder surfaces on one light ray",
                                 out.layers, out.depthComplexity));
  } else if (fraction >= kSeparateFraction) {
    out.layers = 3;
    out.reasons.push_back(
        format("layers 3: on %.0f%% of the probes' light rays in view two occluders lie one "
               "behind the other with free space between them (up to %.0f texels), which two "
               "layers treat as solid",
               100.0 * fraction, widestGap));
  } else {
    out.layers = 2;
    out.reasons.push_back(
        format("layers 2: at most %.0f occluder surfaces on one light ray", out.depthComplexity) +
        format(", and free space between two occluders on %.0f%% of the probes' light rays in "
               "view (three layers from %.0f%%)",
               100.0 * fraction, 100.0 * kSeparateFraction));
  }
}

// How far the normal offset's lift moves the receiver's penumbra, per texel of offset, in
// texels (bias.glsl: normal_offset texel widths along the receiver's normal n). Its part
// along the light's axis f, (n . f) f, lifts the point towards the light; carried along the
// light's ray from the light's centre (direction) to the plane through the receiver normal to
// the axis (where the penumbra's width is measured), that lift moves the point across the
// rays by |n . f| tan(angle between the ray and the axis): nothing under the light, twice the
// lift at the edge of a 127-degree frustum (tan 63 degrees). The penumbra moves with the
// point (a linear ramp: about shift / width mean |error| across it). The offset's part across
// the axis (a box's side face) is what the offset is for, and as large at any frustum: not
// counted.
double liftShiftPerOffset(const glm::vec3& normal, const glm::vec3& direction,
                          const glm::vec3& forward) {
  const float along = glm::dot(direction, forward);
  if (along <= 1e-6f || glm::dot(normal, normal) <= 0.0f) return 0.0;
  const float slant = glm::length(forward - direction / along);  // tan of the ray's angle
  return double(std::fabs(glm::dot(glm::normalize(normal), forward)) * slant);
}

// Runs work(begin, end, part) over [0, count) cut into at most kChunks runs in order (each
// part starting as `initial`), shared
// out to the CPU's threads (Embree's queries are thread-safe), and returns the runs' parts in
// that order: joined, the same results in the same order whatever the thread count. `rays`
// of each part: the rays its run cast.
inline constexpr size_t kChunks = 64, kItemsPerThreadAtLeast = 256;
template <class Part, class Work>
std::vector<Part> inChunks(size_t count, const Work& work, const Part& initial = Part{}) {
  const size_t chunks = std::min(kChunks, std::max<size_t>(1, count));
  std::vector<Part> parts(chunks, initial);
  std::atomic<size_t> next{0};
  const auto worker = [&] {
    for (size_t c = next++; c < chunks; c = next++) {
      const std::uint64_t before = sceneRaysOnThisThread();
      work(c * count / chunks, (c + 1) * count / chunks, parts[c]);
      parts[c].rays = sceneRaysOnThisThread() - before;
    }
  };
  const size_t threads = std::clamp<size_t>(count / kItemsPerThreadAtLeast, 1,
                                      std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (size_t i = 1; i < std::min(threads, chunks); ++i) pool.emplace_back(worker);
  worker();
  for (std::thread& thread : pool) thread.join();
  return parts;
}

template <class T>
void appendTo(std::vector<T>& to, const std::vector<T>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

// What the probes of some of the occluders' triangles measured (steps 1-2).
struct ProbeSet {
  std::vector<double> widthsWorld, texelsPerResolution, widthsPixels, areasPixels;
  std::vector<unsigned> objects;  // the scene object each of those probes lies on
  // Step 4's texels per unit resolution, divided by how many more than kPenumbraTexels the
  // normal offset's lift asks for.
  std::vector<double> resolvingTexelsPerResolution;
  // Step 5's probes in view: the probe's point and its triangle's centroid.
  std::vector<std::pair<glm::vec3, glm::vec3>> inView;
  int depthComplexity = 0;
  std::uint64_t rays = 0;
  void append(const ProbeSet& more) {
    appendTo(widthsWorld, more.widthsWorld);
    appendTo(texelsPerResolution, more.texelsPerResolution);
    appendTo(resolvingTexelsPerResolution, more.resolvingTexelsPerResolution);
    appendTo(widthsPixels, more.widthsPixels);
    appendTo(areasPixels, more.areasPixels);
    appendTo(objects, more.objects);
    appendTo(inView, more.inView);
    depthComplexity = std::max(depthComplexity, more.depthComplexity);
    rays += more.rays;
  }
};

// The view and light quantities every probe uses.
struct ProbeView {
  glm::mat4 viewFromWorld;
  float tanX, tanY, pixelAngle, lightSide, tanHalfFov;
  double normalOffsetTexels;  // light.normal_offset (the lift of step 4)
};

// The most occluder surfaces counted on one light ray (step 5's depth complexity).
inline constexpr int kMostCrossings = 8;

// Steps 1-2 for the 12 probes of one triangle (t = 0, 1/4, 1/2, 3/4 of each edge).
void probeTriangle(const Scene& scene, const SceneRays& rays, const LightFrame& light,
                   const ProbeView& v, unsigned object, size_t t, ProbeSet& out) {
  const Mesh& mesh = scene.objects[object].mesh;
  const Camera& camera = scene.camera;
  for (int e = 0; e < 3; ++e)
    for (float along : {0.0f, 0.25f, 0.5f, 0.75f}) {
      const glm::vec3 a = mesh.positions[mesh.indices[t + e]];
      const glm::vec3 b = mesh.positions[mesh.indices[t + (e + 1) % 3]];
      const glm::vec3 q = a + along * (b - a);
      const glm::vec3 fromLight = q - scene.light.center;
      const float occluderDepth = glm::dot(fromLight, light.forward);
      if (occluderDepth <= 0) continue;  // not in front of the light
      const glm::vec3 direction = glm::normalize(fromLight);
      // The next surface past the occluder along the light's ray, and the occluder
      // surfaces the whole ray crosses from the light (depth complexity).
      const float epsilon = 1e-4f * std::max(1.0f, glm::length(q));
      unsigned geometry;
      glm::vec3 receiverNormal(0);
      const float t1 = rays.hit(q, direction, epsilon, geometry, &receiverNormal);
      if (!std::isfinite(t1)) continue;
      const glm::vec3 receiver = q + t1 * direction;
      // Only their most counts (at most kMostCrossings): once a probe of this set, or of
      // the first ones (castProbes), has met that many, no other can raise it, and the
      // walk is skipped.
      if (out.depthComplexity < kMostCrossings) {
        int crossings = 0;
        float tFrom = 0;
        for (int k = 0; k < kMostCrossings; ++k) {
          unsigned g;
          const float tk = rays.hit(scene.light.center, direction, tFrom, g);
          if (!std::isfinite(tk) || !rays.occluder[g]) break;
          ++crossings;
          tFrom = tk + 1e-4f * std::max(1.0f, tk);
        }
        out.depthComplexity = std::max(out.depthComplexity, crossings);
      }
      // 2. Only what the camera sees.
      const glm::vec3 view = glm::vec3(v.viewFromWorld * glm::vec4(receiver, 1));
      const float eyeDepth = -view.z;
      if (eyeDepth <= 0 || std::fabs(view.x) > v.tanX * eyeDepth ||
          std::fabs(view.y) > v.tanY * eyeDepth)
        continue;
      const glm::vec3 centroid = (mesh.positions[mesh.indices[t]] + mesh.positions[mesh.indices[t + 1]] +
                                  mesh.positions[mesh.indices[t + 2]]) / 3.0f;
      out.inView.emplace_back(q, centroid);
      const float gap = glm::dot(receiver - q, light.forward);
      const double width = double(v.lightSide) * gap / occluderDepth;
      const float receiverZ = glm::dot(receiver - light.wsProjectionPoint, light.forward);
      out.widthsWorld.push_back(width);
      out.texelsPerResolution.push_back(width / (2.0 * receiverZ * v.tanHalfFov));
      // The lift shifts this penumbra by liftTexels texels of the map: at most
      // kLiftShiftFraction of its width when it spans liftTexels / kLiftShiftFraction.
      const double liftTexels =
          v.normalOffsetTexels * liftShiftPerOffset(receiverNormal, direction, light.forward);
      out.resolvingTexelsPerResolution.push_back(
          out.texelsPerResolution.back() * kPenumbraTexels /
          std::max(kPenumbraTexels, liftTexels / kLiftShiftFraction));
      const double pixelWorld = glm::length(receiver - camera.position) * v.pixelAngle;
      out.widthsPixels.push_back(width / pixelWorld);
      // The penumbra strip this probe stands for: its width times the quarter edge's
      // shadow (scaled by receiver / occluder distance from the light), in pixels.
      const float receiverFromLight = glm::dot(receiver - scene.light.center, light.forward);
      const double stripPixels =
          0.25 * glm::length(b - a) * receiverFromLight / occluderDepth / pixelWorld;
      out.areasPixels.push_back(out.widthsPixels.back() * stripPixels);
      out.objects.push_back(object);
    }
}

// Steps 1-2 over every stride-th occluder triangle, in scene order.
ProbeSet castProbes(const Scene& scene, const SceneRays& rays, const LightFrame& light,
                    const ProbeView& view, size_t stride) {
  std::vector<std::pair<unsigned, size_t>> sampled;  // (object, first index of the triangle)
  size_t seen = 0;
  for (unsigned o = 0; o < scene.objects.size(); ++o) {
    const SceneObject& object = scene.objects[o];
    if (object.receiverOnly) continue;
    for (size_t t = 0; t + 2 < object.mesh.indices.size(); t += 3)
      if (seen++ % stride == 0) sampled.emplace_back(o, t);
  }
  // The first 1/kChunks of the triangles first, on this thread: where its probes already
  // count the most crossings, no other probe walks them (the same maximum, fewer rays).
  const size_t first = sampled.size() / kChunks;
  ProbeSet all;
  const std::uint64_t raysBefore = sceneRaysOnThisThread();
  for (size_t i = 0; i < first; ++i)
    probeTriangle(scene, rays, light, view, sampled[i].first, sampled[i].second, all);
  all.rays = sceneRaysOnThisThread() - raysBefore;
  ProbeSet initial;
  if (all.depthComplexity == kMostCrossings) initial.depthComplexity = kMostCrossings;
  for (const ProbeSet& part : inChunks<ProbeSet>(
           sampled.size() - first,
           [&](size_t begin, size_t end, ProbeSet& out) {
             for (size_t i = first + begin; i < first + end; ++i)
               probeTriangle(scene, rays, light, view, sampled[i].first, sampled[i].second, out);
           },
           initial))
    all.append(part);
  return all;
}

// Step 5's free gap on each in-view probe's light ray, in their order.
struct GapSet {
  std::vector<double> gapsPerResolution;
  std::uint64_t rays = 0;
};
GapSet castGapProbes(const Scene& scene, const SceneRays& rays, const LightFrame& light,
                     const std::vector<std::pair<glm::vec3, glm::vec3>>& inView) {
  GapSet all;
  for (const GapSet& part : inChunks<GapSet>(inView.size(), [&](size_t begin, size_t end, GapSet& out) {
         for (size_t i = begin; i < end; ++i)
           out.gapsPerResolution.push_back(
               freeGapTexelsPerResolution(rays, scene.light, light, inView[i].first, inView[i].second));
       })) {
    appendTo(all.gapsPerResolution, part.gapsPerResolution);
    all.rays += part.rays;
  }
  return all;
}

AutoSettings analyze(const Scene& scene, const SceneRays& rays, const LightFrame& light,
                     int eyeWidth, int eyeHeight, double normalOffsetTexels,
                     std::uint64_t& raysCast) {
  AutoSettings out;
  const Camera& camera = scene.camera;
  ProbeView view;
  view.viewFromWorld = glm::lookAt(camera.position, camera.target, camera.up);
  view.tanY = std::tan(glm::radians(camera.fovYDegrees) * 0.5f);
  view.tanX = view.tanY * float(eyeWidth) / float(std::max(eyeHeight, 1));
  view.pixelAngle = 2.0f * view.tanY / float(std::max(eyeHeight, 1));
  view.lightSide = std::min(scene.light.width, scene.light.height);
  view.tanHalfFov = std::max(light.tanHalfFovX, light.tanHalfFovY);
  view.normalOffsetTexels = normalOffsetTexels;
  const float tanHalfFov = view.tanHalfFov;
  size_t triangles = 0;
  for (const SceneObject& object : scene.objects)
    if (!object.receiverOnly) triangles += object.mesh.triangleCount();
  const size_t stride = std::max<size_t>(1, 3 * triangles / kMaxProbes);

  // 1-2. Probes along the occluders' edges.
  ProbeSet probes = castProbes(scene, rays, light, view, stride);
  raysCast += probes.rays;
  out.depthComplexity = probes.depthComplexity;
  const std::vector<double>& widthsWorld = probes.widthsWorld;
  const std::vector<double>& texelsPerResolution = probes.texelsPerResolution;
  const std::vector<double>& resolvingTexelsPerResolution = probes.resolvingTexelsPerResolution;
  const std::vector<double>& widthsPixels = probes.widthsPixels;
  const std::vector<double>& areasPixels = probes.areasPixels;
  // Step 5's free gaps decide only where the depth complexity does not (at most two
  // surfaces on every light ray); with more, three layers whatever they are, and their rays
  // are not cast.
  GapSet gaps;
  if (out.depthComplexity <= 2) gaps = castGapProbes(scene, rays, light, probes.inView);
  raysCast += gaps.rays;
  const std::vector<double>& gapsPerResolution = gaps.gapsPerResolution;
  out.probes = int(widthsWorld.size());
  if (widthsWorld.empty()) {
    out.reasons.push_back("no occluder's shadow falls in view: fixed defaults (512, two layers, 2x2)");
    return out;
  }
  // 3. Rays (before the map: the map's budget depends on them).
  out.smallestPenumbraPixels = percentile(widthsPixels, 0.02);
  const double sigma = std::min(2.0, 0.5 * out.smallestPenumbraPixels);
  const double filterPixels = std::max(1.0, M_PI * sigma * sigma);
  out.raysPerSide = 2;
  while (out.raysPerSide < 8 && out.raysPerSide * out.raysPerSide * filterPixels < kEffectiveSamples)
    ++out.raysPerSide;
  // 4. Resolution: what the penumbrae need, weighed by the shadow area they hold, and what
  //    the map may cost next to the trace.
  const auto resolutionFor = [](double texelsPerUnitResolution) {  // kPenumbraTexels across
    return kPenumbraTexels / std::max(texelsPerUnitResolution, 1e-9);
  };
  // The smallest map: 256 at a 90-degree frustum, and as many more texels as a wider frustum
  // (light.fov_degrees=auto, auto_frustum.h) spreads over its larger cross-section, so that a
  // texel is no wider in the world than at 256 and 90 degrees (docs/decisions/150).
  const int floorResolution = int(std::min(
      2048.0, std::ceil(kMinResolution * std::max(1.0, double(tanHalfFov)) / 128.0) * 128.0));
  const auto roundUp = [floorResolution](double resolution) {
    return int(std::clamp(std::ceil(resolution / 128.0) * 128.0, double(floorResolution), 2048.0));
  };
  const double needed = resolutionFor(weightedPercentile(resolvingTexelsPerResolution, areasPixels, 0.02));
  out.neededResolution = roundUp(needed);
  out.halfAreaResolution = roundUp(resolutionFor(weightedPercentile(resolvingTexelsPerResolution, areasPixels, 0.5)));
  // What the penumbrae alone would need (without the lift), for the reason.
  const int penumbraResolution = roundUp(resolutionFor(weightedPercentile(texelsPerResolution, areasPixels, 0.02)));
  // The crossover measured on this renderer (gl/renderer_calibration.h; kTexelLevelsPerPixelRay
  // where it is not calibrated).
  const double traceWork = activeRendererCalibration().texelLevelsPerPixelRay * double(eyeWidth) * double(eyeHeight) *
                           double(out.raysPerSide * out.raysPerSide);
  out.affordableResolution = 256;
  while (out.affordableResolution < 2048 && mapBuildWork(out.affordableResolution + 128) <= traceWork)
    out.affordableResolution += 128;
  // The steep occluders' images (occluder_image.h): the map on which the steep occluders
  // holding 98% of the penumbra area span kOccluderImageTexels across their narrowest
  // extent (the others count as wide). Its own need, beside the penumbrae's, and above the
  // cost cap: a steep occluder drawn by a few texel centres is too bright or too dark in all
  // of its shadow, not in a part of it.
  // A steep occluder whose image is under a texel wide even at 2048 (a sheet exactly edge-on
  // to the light's centre) is in no map: no size helps, so it is left out of the need and
  // named in a warning.
  const SteepOccluders steep =
      steepOccluders(scene, light, probes.objects, areasPixels, kSteepDepthOverWidth, 2048);
  out.narrowestOccluderImage = steep.narrowestImage;
  if (!steep.inNoMap.empty())
    out.warning = "WARNING: occluder " + quotedNames(steep.inNoMap) +
                  " is edge-on to the light's centre: its image in the light's map is under a "
                  "texel wide even at 2048, so the depth layers do not hold it and the methods "
                  "that read them (trace, PCSS, SSM, hard shadow) miss its shadow; the "
                  "reference and raster4d see it (docs/decisions/156)";
  const double imageNeeded = kOccluderImageTexels / std::max(out.narrowestOccluderImage, 1e-9);
  out.occluderImageResolution = roundUp(imageNeeded);
  const int penumbraNeededResolution = out.neededResolution;
  out.neededResolution = std::max(out.neededResolution, out.occluderImageResolution);
  out.resolution = std::min(out.neededResolution,
                            std::max({out.affordableResolution, out.halfAreaResolution,
                                      out.occluderImageResolution}));
  out.ssmNeed = ssmResolutionNeeded(texelsPerResolution, areasPixels);  // auto_ssm.h
  out.smallestPenumbraWorld = percentile(widthsWorld, 0.02);
  out.smallestPenumbraTexels = percentile(texelsPerResolution, 0.02) * out.resolution;
  if (out.resolution == out.neededResolution &&
      out.occluderImageResolution > penumbraNeededResolution) {
    out.reasons.push_back(format(
        "map %.0f: the steep occluders (at least twice as deep along the light's rays as "
        "their image is wide) holding 98%% of the penumbra area in view span at least %.0f "
        "texels across their image in the light's map (the narrowest %.2g texels)",
        out.resolution, kOccluderImageTexels, out.narrowestOccluderImage * out.resolution) +
        format("; %.0f would give their penumbrae 6 texels, but a steep occluder a few texels "
               "wide (a sheet nearly edge-on to the light) is too bright or too dark in all of "
               "its shadow",
               penumbraNeededResolution));
  } else if (out.resolution == out.neededResolution) {
    out.reasons.push_back(format(
        "map %.0f: 98%% of the penumbra area in view spans at least 6 texels; the narrowest "
        "penumbra is %.3g world units wide, %.2g texels",
        out.resolution, out.smallestPenumbraWorld, out.smallestPenumbraTexels));
    if (out.resolution > penumbraResolution)
      out.reasons.back() += format(
          "; not %.0f, so that the normal offset's lift (%.2g texel) moves it by at most %.0f%% of "
          "its width where the light's rays reach the receivers at a slant",
          penumbraResolution, normalOffsetTexels, 100.0 * kLiftShiftFraction);
    else if (out.resolution == floorResolution && floorResolution > kMinResolution)
      out.reasons.back() += format(
          "; at least %.0f: the light's frustum is %.0f degrees wide, and its texels as wide in "
          "the world as %.0f's at 90 degrees",
          floorResolution, 2.0 * std::atan(double(tanHalfFov)) * 180.0 / M_PI, kMinResolution);
  } else {
    out.reasons.push_back(format(
        "map %.0f, not the %.0f that would give 98%% of the penumbra area 6 texels: a larger "
        "map's build would cost more than the trace",
        out.resolution, out.neededResolution) +
        (out.neededResolution > penumbraResolution
             ? format(" (%.0f for the penumbrae alone; the rest so that the normal offset's lift "
                      "moves them by at most %.0f%% of their width)",
                      penumbraResolution, 100.0 * kLiftShiftFraction)
             : std::string()) +
        format(" (%.0fx%.0f rays per pixel)", out.raysPerSide, out.raysPerSide) +
        format(", and the penumbrae holding half that area need only %.0f", out.halfAreaResolution));
  }
  if (needed > 2048.0 && out.resolution == 2048)
    out.reasons.push_back(format("the %.0f^2 map that would give it %.0f texels exceeds the "
                                 "2048 limit: expect the narrowest shadows too sharp or too bright",
                                 needed, kPenumbraTexels));
  if (imageNeeded > 2048.0 && out.resolution == 2048)
    out.reasons.push_back(format("the %.0f^2 map on which the narrowest steep occluder's image "
                                 "would span %.0f texels exceeds the 2048 limit: at 2048 it "
                                 "spans %.2g, and its shadow may be too bright or too dark by a "
                                 "texel of that",
                                 imageNeeded, kOccluderImageTexels,
                                 out.narrowestOccluderImage * out.resolution));
  out.reasons.push_back(
      format("rays %.0fx%.0f: the narrowest penumbra is %.2g pixels wide", out.raysPerSide,
             out.raysPerSide, out.smallestPenumbraPixels) +
      format(", the filter averages about %.2g pixels there, and %.0f rays per pixel give at "
             "least 24 samples",
             filterPixels, out.raysPerSide * out.raysPerSide));
  // 5. Layers.
  chooseLayers(gapsPerResolution, out);
  return out;
}

}  // namespace

namespace {
std::mutex workMutex;           // the cache below and the counts
AutoSettingsWork workSoFar;
}  // namespace

AutoSettingsWork autoSettingsWork() {
  const std::lock_guard<std::mutex> lock(workMutex);
  return workSoFar;
}

AutoSettings chooseAutoSettings(const Scene& scene, const LightFrame& light, int eyeWidth,
                                int eyeHeight, double normalOffsetTexels) {
  // One cached answer and one Embree scene, for the last scene seen (the window and the
  // tests run one scene at a time).
  struct Cache {
    std::uint64_t geometry = 0;
    std::unique_ptr<SceneRays> rays;
    std::vector<float> key;
    AutoSettings settings;
  };
  static Cache cache;
  const std::lock_guard<std::mutex> lock(workMutex);
  AutoSettingsWork& work = workSoFar;
  // FNV-1a over every position, index and flag, a 32-bit word at a time (this runs on every
  // light run: a quarter of the steps of a byte-wise hash on the dragon's 1.6 MB).
  std::uint64_t geometry = 1469598103934665603ull;
  auto mix = [&](const void* data, size_t words) {
    for (size_t i = 0; i < words; ++i) {
      std::uint32_t word;
      std::memcpy(&word, static_cast<const char*>(data) + 4 * i, 4);
      geometry = (geometry ^ word) * 1099511628211ull;
    }
  };
  for (const SceneObject& object : scene.objects) {
    mix(object.mesh.positions.data(), object.mesh.positions.size() * 3);
    mix(object.mesh.indices.data(), object.mesh.indices.size());
    const std::uint32_t receiverOnly = object.receiverOnly;
    mix(&receiverOnly, 1);
  }
  if (!cache.rays || cache.geometry != geometry) {
    cache.rays.reset();  // the old scene's memory back before the new one's
    cache.rays = std::make_unique<SceneRays>(scene);
    cache.geometry = geometry;
    cache.key.clear();
    ++work.bvhBuilds;
  }
  const Camera& c = scene.camera;
  const AreaLight& l = scene.light;
  std::vector<float> key = {c.position.x, c.position.y, c.position.z, c.target.x, c.target.y,
                            c.target.z, c.up.x, c.up.y, c.up.z, c.fovYDegrees, l.center.x,
                            l.center.y, l.center.z, l.forward.x, l.forward.y, l.forward.z,
                            l.width, l.height, light.tanHalfFovX, float(eyeWidth), float(eyeHeight),
                            float(activeRendererCalibration().texelLevelsPerPixelRay),
                            float(normalOffsetTexels)};
  if (key != cache.key) {
    cache.settings = analyze(scene, *cache.rays, light, eyeWidth, eyeHeight, normalOffsetTexels, work.rays);
    cache.key = key;
    ++work.analyses;
  }
  return cache.settings;
}

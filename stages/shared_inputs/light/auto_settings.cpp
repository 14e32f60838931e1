#include "shared_inputs/light/auto_settings.h"

#include "gl/renderer_calibration.h"
#include "shared_inputs/weighted_percentile.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <memory>
#include <mutex>

namespace {

// Every triangle of the scene (receivers too: the penumbra falls on them), with which
// geometry ids are occluders.
struct SceneRays {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<bool> occluder;  // by geometry id
  explicit SceneRays(const Scene& source) {
    device = rtcNewDevice(nullptr);
    scene = rtcNewScene(device);
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    for (const SceneObject& object : source.objects) {
      const Mesh& mesh = object.mesh;
      RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
          geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
          std::max<size_t>(mesh.positions.size(), 1)));
      auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
          geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
          mesh.triangleCount()));
      for (size_t i = 0; i < mesh.positions.size(); ++i)
        for (int c = 0; c < 3; ++c) vertices[3 * i + c] = mesh.positions[i][c];
      for (size_t i = 0; i < mesh.indices.size(); ++i) indices[i] = mesh.indices[i];
      rtcCommitGeometry(geometry);
      occluder.push_back(!object.receiverOnly);
      rtcAttachGeometry(scene, geometry);  // ids 0, 1, ... in order
      rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(scene);
  }
  ~SceneRays() {
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
  }
  // Nearest hit along origin + t direction, t in (tNear, inf): t (inf: none), geometry id and,
  // when asked, the geometric normal there.
  float hit(const glm::vec3& origin, const glm::vec3& direction, float tNear, unsigned& geometry,
            glm::vec3* normal = nullptr) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit query{};
    query.ray.org_x = origin.x; query.ray.org_y = origin.y; query.ray.org_z = origin.z;
    query.ray.dir_x = direction.x; query.ray.dir_y = direction.y; query.ray.dir_z = direction.z;
    query.ray.tnear = tNear;
    query.ray.tfar = std::numeric_limits<float>::infinity();
    query.ray.mask = 0xffffffffu;
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &query);
    geometry = query.hit.geomID;
    if (normal) *normal = glm::vec3(query.hit.Ng_x, query.hit.Ng_y, query.hit.Ng_z);
    return geometry == RTC_INVALID_GEOMETRY_ID ? std::numeric_limits<float>::infinity()
                                               : query.ray.tfar;
  }
};

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

AutoSettings analyze(const Scene& scene, const SceneRays& rays, const LightFrame& light,
                     int eyeWidth, int eyeHeight) {
  AutoSettings out;
  const Camera& camera = scene.camera;
  const glm::mat4 viewFromWorld = glm::lookAt(camera.position, camera.target, camera.up);
  const float tanY = std::tan(glm::radians(camera.fovYDegrees) * 0.5f);
  const float tanX = tanY * float(eyeWidth) / float(std::max(eyeHeight, 1));
  const float pixelAngle = 2.0f * tanY / float(std::max(eyeHeight, 1));
  const float lightSide = std::min(scene.light.width, scene.light.height);
  const float tanHalfFov = std::max(light.tanHalfFovX, light.tanHalfFovY);
  size_t triangles = 0;
  for (const SceneObject& object : scene.objects)
    if (!object.receiverOnly) triangles += object.mesh.triangleCount();
  const size_t stride = std::max<size_t>(1, 3 * triangles / kMaxProbes);

  // 1-2. Probes along the occluders' edges (t = 0, 1/4, 1/2, 3/4 of each edge).
  std::vector<double> widthsWorld, texelsPerResolution, widthsPixels, areasPixels;
  std::vector<double> gapsPerResolution;  // step 5: the free gap on each probe's light ray
  size_t seen = 0;
  for (unsigned id = 0; id < scene.objects.size(); ++id) {
    const SceneObject& object = scene.objects[id];
    if (object.receiverOnly) continue;
    const Mesh& mesh = object.mesh;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      if (seen++ % stride != 0) continue;
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
          const float t1 = rays.hit(q, direction, epsilon, geometry);
          if (!std::isfinite(t1)) continue;
          const glm::vec3 receiver = q + t1 * direction;
          int crossings = 0;
          float tFrom = 0;
          for (int k = 0; k < 8; ++k) {
            unsigned g;
            const float tk = rays.hit(scene.light.center, direction, tFrom, g);
            if (!std::isfinite(tk) || !rays.occluder[g]) break;
            ++crossings;
            tFrom = tk + 1e-4f * std::max(1.0f, tk);
          }
          out.depthComplexity = std::max(out.depthComplexity, crossings);
          // 2. Only what the camera sees.
          const glm::vec3 view = glm::vec3(viewFromWorld * glm::vec4(receiver, 1));
          const float eyeDepth = -view.z;
          if (eyeDepth <= 0 || std::fabs(view.x) > tanX * eyeDepth ||
              std::fabs(view.y) > tanY * eyeDepth)
            continue;
          const glm::vec3 centroid = (mesh.positions[mesh.indices[t]] + mesh.positions[mesh.indices[t + 1]] +
                                      mesh.positions[mesh.indices[t + 2]]) / 3.0f;
          gapsPerResolution.push_back(freeGapTexelsPerResolution(rays, scene.light, light, q, centroid));
          const float gap = glm::dot(receiver - q, light.forward);
          const double width = double(lightSide) * gap / occluderDepth;
          const float receiverZ = glm::dot(receiver - light.wsProjectionPoint, light.forward);
          widthsWorld.push_back(width);
          texelsPerResolution.push_back(width / (2.0 * receiverZ * tanHalfFov));
          const double pixelWorld = glm::length(receiver - camera.position) * pixelAngle;
          widthsPixels.push_back(width / pixelWorld);
          // The penumbra strip this probe stands for: its width times the quarter edge's
          // shadow (scaled by receiver / occluder distance from the light), in pixels.
          const float receiverFromLight = glm::dot(receiver - scene.light.center, light.forward);
          const double stripPixels =
              0.25 * glm::length(b - a) * receiverFromLight / occluderDepth / pixelWorld;
          areasPixels.push_back(widthsPixels.back() * stripPixels);
        }
    }
  }
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
  const auto roundUp = [](double resolution) {
    return int(std::clamp(std::ceil(resolution / 128.0) * 128.0, 256.0, 2048.0));
  };
  const double needed = resolutionFor(weightedPercentile(texelsPerResolution, areasPixels, 0.02));
  out.neededResolution = roundUp(needed);
  out.halfAreaResolution = roundUp(resolutionFor(weightedPercentile(texelsPerResolution, areasPixels, 0.5)));
  // The crossover measured on this renderer (gl/renderer_calibration.h; kTexelLevelsPerPixelRay
  // where it is not calibrated).
  const double traceWork = activeRendererCalibration().texelLevelsPerPixelRay * double(eyeWidth) * double(eyeHeight) *
                           double(out.raysPerSide * out.raysPerSide);
  out.affordableResolution = 256;
  while (out.affordableResolution < 2048 && mapBuildWork(out.affordableResolution + 128) <= traceWork)
    out.affordableResolution += 128;
  out.resolution = std::min(out.neededResolution,
                            std::max(out.affordableResolution, out.halfAreaResolution));
  out.ssmNeed = ssmResolutionNeeded(texelsPerResolution, areasPixels);  // auto_ssm.h
  out.smallestPenumbraWorld = percentile(widthsWorld, 0.02);
  out.smallestPenumbraTexels = percentile(texelsPerResolution, 0.02) * out.resolution;
  if (out.resolution == out.neededResolution) {
    out.reasons.push_back(format(
        "map %.0f: 98%% of the penumbra area in view spans at least 6 texels; the narrowest "
        "penumbra is %.3g world units wide, %.2g texels",
        out.resolution, out.smallestPenumbraWorld, out.smallestPenumbraTexels));
  } else {
    out.reasons.push_back(format(
        "map %.0f, not the %.0f that would give 98%% of the penumbra area 6 texels: a larger "
        "map's build would cost more than the trace",
        out.resolution, out.neededResolution) +
        format(" (%.0fx%.0f rays per pixel)", out.raysPerSide, out.raysPerSide) +
        format(", and the penumbrae holding half that area need only %.0f", out.halfAreaResolution));
  }
  if (needed > 2048.0 && out.resolution == 2048)
    out.reasons.push_back(format("the %.0f^2 map that would give it %.0f texels exceeds the "
                                 "2048 limit: expect the narrowest shadows too sharp or too bright",
                                 needed, kPenumbraTexels));
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

AutoSettings chooseAutoSettings(const Scene& scene, const LightFrame& light, int eyeWidth,
                                int eyeHeight) {
  // One cached answer and one Embree scene, for the last scene seen (the window and the
  // tests run one scene at a time).
  struct Cache {
    std::uint64_t geometry = 0;
    std::unique_ptr<SceneRays> rays;
    std::vector<float> key;
    AutoSettings settings;
  };
  static std::mutex mutex;
  static Cache cache;
  const std::lock_guard<std::mutex> lock(mutex);
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
    cache.rays = std::make_unique<SceneRays>(scene);
    cache.geometry = geometry;
    cache.key.clear();
  }
  const Camera& c = scene.camera;
  const AreaLight& l = scene.light;
  std::vector<float> key = {c.position.x, c.position.y, c.position.z, c.target.x, c.target.y,
                            c.target.z, c.up.x, c.up.y, c.up.z, c.fovYDegrees, l.center.x,
                            l.center.y, l.center.z, l.forward.x, l.forward.y, l.forward.z,
                            l.width, l.height, light.tanHalfFovX, float(eyeWidth), float(eyeHeight),
                            float(activeRendererCalibration().texelLevelsPerPixelRay)};
  if (key != cache.key) {
    cache.settings = analyze(scene, *cache.rays, light, eyeWidth, eyeHeight);
    cache.key = key;
  }
  return cache.settings;
}

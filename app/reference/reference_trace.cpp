#include "reference/reference_trace.h"

#include "core/run_control.h"

#include <embree3/rtcore.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <thread>

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A fixed integer hash (Wang/"lowbias32"-style avalanche): deterministic jitter that does
// not depend on any library's random generator.
std::uint32_t mix32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

float unitFloat(std::uint32_t bits) { return float(bits >> 8) * (1.0f / 16777216.0f); }

// Embree asserts on rays past 1.8e18 (ray.valid()); scenes are limited to kMaxCoordinate
// (app/scene/scene.h), so a point beyond twice that is refused here, before Embree sees it.
bool representable(const float* p) {
  return std::abs(p[0]) <= 2 * kMaxCoordinate && std::abs(p[1]) <= 2 * kMaxCoordinate &&
         std::abs(p[2]) <= 2 * kMaxCoordinate;
}

void checkInRange(const ReferenceRequest& request) {
  const float light[3] = {request.wsLightCenter.x, request.wsLightCenter.y, request.wsLightCenter.z};
  bool inRange = representable(light) && request.halfWidth <= kMaxCoordinate &&
                 request.halfHeight <= kMaxCoordinate;
  for (size_t i = 0; inRange && i < request.wsPosition.size() / 4; ++i)
    inRange = request.wsPosition[4 * i + 3] <= 0 || representable(&request.wsPosition[4 * i]);
  if (!inRange)
    throw std::runtime_error("reference: a point or the light lies beyond the scene limit of "
                             "+-1e6 (app/scene/scene.h); Embree cannot trace it");
}

void throwOnDeviceError(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("Embree: ") + what + " failed (error " +
                             std::to_string(int(error)) + ")");
}

}  // namespace

glm::vec2 referenceSampleUnit(int x, int y, int k, int samplesPerSide, bool stratified) {
  const int m = samplesPerSide;
  const glm::vec2 cell(float(k % m), float(k / m));
  if (!stratified) return (cell + 0.5f) / float(m);
  const std::uint32_t seed = mix32(std::uint32_t(x) * 0x9e3779b1U ^ mix32(std::uint32_t(y) + 0x632be5abU));
  const std::uint32_t a = mix32(seed ^ mix32(std::uint32_t(k) * 2u + 1u));
  const std::uint32_t b = mix32(a ^ 0x5bd1e995U);
  return (cell + glm::vec2(unitFloat(a), unitFloat(b))) / float(m);
}

float referenceMinimumOffset(const Scene& scene) {
  const Bounds occluders = scene.bounds(/*occludersOnly=*/true);
  return kRelativeEpsilon * 0.1f * (occluders.empty() ? 1.0f : glm::length(occluders.max - occluders.min));
}

float referenceOriginOffset(const ReferenceRequest& request, const glm::vec3& p) {
  const glm::vec3 size = glm::abs(p);
  return std::max(request.minimumEpsilon,
                  request.relativeEpsilon * std::max({size.x, size.y, size.z}));
}

struct ReferenceTracer::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  mutable std::atomic<std::uint64_t> rays{0};
  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  // The rays of one point, in packets of K: count of light samples that reach the light.
  // `blocked` (m * m entries, or null): 1 where light sample k does not reach the point.
  template <int K, typename Packet, typename Occluded>
  int visibleSamples(const ReferenceRequest& r, const glm::vec3& p, const glm::vec3& n, int x,
                     int y, Occluded occluded, std::uint8_t* blocked) const {
    const int m = r.samplesPerSide, total = m * m;
    const glm::vec3 origin = p + referenceOriginOffset(r, p) * n;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // one origin, one light: coherent
    int visible = 0;
    for (int first = 0; first < total; first += K) {
      alignas(64) Packet packet;
      alignas(64) int valid[K];
      int active = 0;
      for (int lane = 0; lane < K; ++lane) {
        const int k = first + lane;
        valid[lane] = 0;
        packet.tfar[lane] = -std::numeric_limits<float>::infinity();
        if (k >= total) continue;
        if (blocked) blocked[k] = 1;
        const glm::vec2 unit = referenceSampleUnit(x, y, k, m, r.stratified);
        const glm::vec3 sample = r.wsLightCenter +
                                 (2 * unit.x - 1) * r.halfWidth * r.wsLightRight +
                                 (2 * unit.y - 1) * r.halfHeight * r.wsLightUp;
        const glm::vec3 direction = sample - origin;  // t = 1 reaches the light sample
        if (glm::dot(n, sample - p) <= 0) continue;   // behind the tangent plane: blocked
        packet.org_x[lane] = origin.x; packet.org_y[lane] = origin.y; packet.org_z[lane] = origin.z;
        packet.dir_x[lane] = direction.x; packet.dir_y[lane] = direction.y; packet.dir_z[lane] = direction.z;
        packet.tnear[lane] = 0;
        packet.tfar[lane] = 1;
        packet.time[lane] = 0;
        packet.mask[lane] = 0xffffffffu;
        packet.id[lane] = unsigned(lane);
        packet.flags[lane] = 0;
        valid[lane] = -1;
        ++active;
      }
      if (active == 0) continue;
      rays += std::uint64_t(active);
      occluded(valid, &context, &packet);
      for (int lane = 0; lane < K; ++lane)
        if (valid[lane] && packet.tfar[lane] >= 0) {  // tfar = -inf when occluded
          ++visible;
          if (blocked) blocked[first + lane] = 0;
        }
    }
    return visible;
  }

  int visibleSamplesNative(int width, const ReferenceRequest& r, const glm::vec3& p,
                           const glm::vec3& n, int x, int y, std::uint8_t* blocked = nullptr) const {
    RTCScene s = scene;
    switch (width) {
      case 16:
        return visibleSamples<16, RTCRay16>(r, p, n, x, y, [s](int* v, RTCIntersectContext* c, RTCRay16* q) { rtcOccluded16(v, s, c, q); }, blocked);
      case 8:
        return visibleSamples<8, RTCRay8>(r, p, n, x, y, [s](int* v, RTCIntersectContext* c, RTCRay8* q) { rtcOccluded8(v, s, c, q); }, blocked);
      case 4:
        return visibleSamples<4, RTCRay4>(r, p, n, x, y, [s](int* v, RTCIntersectContext* c, RTCRay4* q) { rtcOccluded4(v, s, c, q); }, blocked);
      default: {
        // Single rays through the same code: a one-lane "packet" in RTCRay layout.
        struct One {
          float org_x[1], org_y[1], org_z[1], tnear[1], dir_x[1], dir_y[1], dir_z[1], time[1],
              tfar[1];
          unsigned mask[1], id[1], flags[1];
        };
        return visibleSamples<1, One>(r, p, n, x, y, [s](int* v, RTCIntersectContext* c, One* q) {
          RTCRay ray{q->org_x[0], q->org_y[0], q->org_z[0], q->tnear[0], q->dir_x[0], q->dir_y[0],
                     q->dir_z[0], q->time[0], q->tfar[0], q->mask[0], q->id[0], q->flags[0]};
          rtcOccluded1(s, c, &ray);
          q->tfar[0] = ray.tfar;
        }, blocked);
      }
    }
  }
};

ReferenceTracer::ReferenceTracer(const Scene& sceneIn) : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device)
    throw std::runtime_error("Embree: cannot create a device (error " +
                             std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
  RTCDevice device = impl_->device;
  impl_->scene = rtcNewScene(device);
  // Robust: watertight traversal, so no ray leaks between two triangles sharing an edge.
  rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);
  for (const SceneObject& object : sceneIn.objects) {
    if (object.receiverOnly) continue;  // casts no shadow in any method (thesis §3.3)
    const Mesh& mesh = object.mesh;
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
        mesh.positions.size()));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
        mesh.triangleCount()));
    throwOnDeviceError(device, "geometry buffers");
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      if (!representable(&mesh.positions[i].x)) {
        rtcReleaseGeometry(geometry);
        throw std::runtime_error("reference: object '" + object.name + "' has a vertex beyond "
                                 "the scene limit (app/scene/scene.h)");
      }
      for (int c = 0; c < 3; ++c) vertices[3 * i + c] = mesh.positions[i][c];
    }
    for (size_t i = 0; i < mesh.indices.size(); ++i) indices[i] = mesh.indices[i];
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(impl_->scene, geometry);
    rtcReleaseGeometry(geometry);
    triangles_ += mesh.triangleCount();
  }
  rtcCommitScene(impl_->scene);
  throwOnDeviceError(device, "scene build");
  if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED)) packetWidth_ = 16;
  else if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED)) packetWidth_ = 8;
  else if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY4_SUPPORTED)) packetWidth_ = 4;
  if (const char* forced = std::getenv("PENUMBRA_REFERENCE_PACKET")) packetWidth_ = std::atoi(forced);
}

ReferenceTracer::~ReferenceTracer() = default;

std::uint64_t ReferenceTracer::raysCast() const { return impl_->rays; }

float ReferenceTracer::pointVisibility(const ReferenceRequest& request, const glm::vec3& p,
                                       const glm::vec3& n, int x, int y) const {
  const int m = request.samplesPerSide;
  return float(impl_->visibleSamplesNative(packetWidth_, request, p, n, x, y)) / float(m * m);
}

std::vector<std::uint8_t> ReferenceTracer::blockedSamples(const ReferenceRequest& request,
                                                         const glm::vec3& p, const glm::vec3& n,
                                                         int x, int y) const {
  const int m = request.samplesPerSide;
  std::vector<std::uint8_t> blocked(size_t(m) * m, 0);
  impl_->visibleSamplesNative(packetWidth_, request, p, n, x, y, blocked.data());
  return blocked;
}

bool ReferenceTracer::trace(const ReferenceRequest& request, std::vector<float>& visibility,
                            ReferenceProgress* progress, int threads) const {
  const int w = request.width, h = request.height;
  if (request.samplesPerSide < 1 || w < 1 || h < 1 ||
      request.wsPosition.size() != size_t(w) * h * 4 || request.wsNormal.size() != size_t(w) * h * 4)
    throw std::invalid_argument("ReferenceTracer::trace: inconsistent request");
  checkInRange(request);  // here: the worker threads must not throw
  visibility.assign(size_t(w) * h, 1.0f);
  if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
  const int tilesX = (w + kTile - 1) / kTile, tilesY = (h + kTile - 1) / kTile;
  const int tiles = tilesX * tilesY;
  threads = std::min(threads, tiles);
  if (progress) {
    progress->tilesTotal = tiles;
    progress->tilesDone = 0;
  }
  std::atomic<int> nextTile{0}, completed{0};
  auto worker = [&] {
    for (int tile = nextTile++; tile < tiles; tile = nextTile++) {
      // Between tiles: a cancel request of its own, or of the whole run (core/run_control.h:
      // Esc or Cancel in the window, a command's --time-limit).
      if ((progress && progress->cancel) || runCancelRequested()) return;
      const int x0 = (tile % tilesX) * kTile, y0 = (tile / tilesX) * kTile;
      for (int y = y0; y < std::min(h, y0 + kTile); ++y)
        for (int x = x0; x < std::min(w, x0 + kTile); ++x) {
          const size_t i = size_t(y) * w + x;
          const float* p = &request.wsPosition[4 * i];
          if (p[3] <= 0) continue;  // background: nothing to shade
          const float* n = &request.wsNormal[4 * i];
          visibility[i] = pointVisibility(request, {p[0], p[1], p[2]}, {n[0], n[1], n[2]}, x, y);
        }
      ++completed;
      if (progress) ++progress->tilesDone;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& thread : pool) thread.join();
  return completed == tiles;  // every tile traced: the image is whole
}

double ReferenceTracer::estimateSeconds(const ReferenceRequest& request, int stride) const {
  checkInRange(request);
  const size_t pixels = size_t(request.width) * request.height;
  size_t covered = 0, timed = 0;
  for (size_t i = 0; i < pixels; ++i) covered += request.wsPosition[4 * i + 3] > 0;
  const auto start = std::chrono::steady_clock::now();
  for (size_t i = 0, seen = 0; i < pixels; ++i) {
    const float* p = &request.wsPosition[4 * i];
    if (p[3] <= 0 || seen++ % size_t(stride) != 0) continue;
    const float* n = &request.wsNormal[4 * i];
    pointVisibility(request, {p[0], p[1], p[2]}, {n[0], n[1], n[2]}, int(i % request.width),
                    int(i / request.width));
    ++timed;
  }
  if (timed == 0) return 0;
  const double perPixel = secondsSince(start) / double(timed);
  const double threads = std::max(1u, std::thread::hardware_concurrency());
  return perPixel * double(covered) / threads;
}

TerminalProgress::TerminalProgress(std::string label, const ReferenceProgress& progress)
    : label_(std::move(label)), progress_(progress), terminal_(isatty(STDERR_FILENO) != 0) {
  started_ = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  if (!terminal_) std::fprintf(stderr, "%s: computing...\n", label_.c_str());
}

void TerminalProgress::update() {
  if (!terminal_) return;
  const double now = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  if (now - lastDraw_ < 0.2) return;
  lastDraw_ = now;
  const int total = std::max(1, progress_.tilesTotal.load()), done = progress_.tilesDone.load();
  const int width = 30, filled = width * done / total;
  const double elapsed = now - started_;
  const double remaining = done > 0 ? elapsed * (total - done) / done : 0;
  std::fprintf(stderr, "\r%s [%s%s] %3d%%  %.1f s, ~%.0f s left ", label_.c_str(),
               std::string(size_t(filled), '#').c_str(), std::string(size_t(width - filled), '.').c_str(),
               100 * done / total, elapsed, remaining);
  std::fflush(stderr);
}

void TerminalProgress::finish(double seconds, bool cancelled) {
  std::fprintf(stderr, "%s%s: %s after %.2f s\n", terminal_ ? "\r" : "", label_.c_str(),
               cancelled ? "cancelled" : "done", seconds);
}

// Exact reference visibility (docs/design.md#ground-truth): at each receiver point, the fraction of
// an m x m grid of light samples that the REAL triangles of the scene do not hide, ray traced on
// the CPU with Embree 3. The stage `reference` (stages/ground_truth/reference/reference.cpp) and `penumbra
// bench` use it; it knows nothing about GL.
//
// Choices, and why (they make it the truth the methods are measured against):
// - Occluders: the objects that are not receiver-only, exactly the set the methods put in
//   their depth layers (light_layers excludes receiver-only objects, thesis §3.3). A
//   receiver-only ground casts no shadow in any method, so it casts none here either.
// - Origin: the receiver point moved along its normal by an offset from the point's own
//   coordinates: kRelativeEpsilon x its largest coordinate (float round-off of the G-buffer
//   point and of Embree's hit test grows with the coordinates' size, not with the scene's),
//   at least kRelativeEpsilon x 0.1 x the diagonal of the occluders (the only triangles in
//   the Embree scene: a receiver-only ground of any size does not count). The methods need
//   the large bias of Eq 3.2 to survive depth-map resolution; the reference only needs to
//   leave the surface's own triangle, so the offset stays tiny near the occluders and does
//   not detach contact shadows (docs/accuracy.md: with 1e-5 x the whole scene's diagonal, a plate
//   0.06 above a 1000-unit ground was 0.066 too bright in shadow).
// - A light sample behind the receiver's tangent plane (n . (s - p) <= 0) is blocked: an
//   opaque surface cannot see through itself. This is what the methods' backface early
//   out (§3.7) and the Lambert term assume; for closed meshes the triangles agree anyway.
// - Sampling: `stratified` jitters one sample inside each of the m x m cells of the light,
//   from a fixed integer hash of (pixel, sample) (decorrelated between pixels, so the
//   sampling error is unbiased noise, not bands; the same input gives the same bits);
//   `uniform` takes the cell centres (a fixed quadrature, for exact methods): exactly the
//   light samples of stage `raster4d` with raster4d.samples = m (sample k = row * m +
//   column, row along up, column along right, both from the light's -width/2, -height/2
//   corner), so the two can be compared bit for bit (tests/stages/test_raster4d_exact.cpp).
// - Light samples use the same parametrisation as the trace (centre + (2u-1) w/2 right +
//   (2v-1) h/2 up, with the light frame's orthonormal right/up).
#pragma once
#include <glm/glm.hpp>

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "shared/reference_origin.h"

// The receivers and the light sampling of one reference image.
struct ReferenceRequest {
  int width = 0, height = 0;
  std::vector<float> wsPosition;  // RGBA per pixel, GL order (row 0 at the bottom); w: coverage
  std::vector<float> wsNormal;    // RGBA per pixel, unit normal towards the eye
  int samplesPerSide = 16;        // m
  bool stratified = true;         // false: cell centres
  glm::vec3 wsLightCenter{0}, wsLightRight{1, 0, 0}, wsLightUp{0, 0, 1};  // right/up unit
  float halfWidth = 0.5f, halfHeight = 0.5f;
  // Origin offset along the normal: max(minimumEpsilon, relativeEpsilon x max|p_i|).
  float relativeEpsilon = 1e-5f;
  float minimumEpsilon = 1e-5f;  // world units
};

// Shared with whoever shows progress or wants to stop a computation (the window, the stage):
// tiles finished so far and a cancel request, both polled from any thread.
struct ReferenceProgress {
  std::atomic<int> tilesDone{0};
  std::atomic<int> tilesTotal{0};
  std::atomic<bool> cancel{false};
  std::atomic<bool> running{false};  // a computation is under way
  std::atomic<int> finished{0};      // completed computations: a change means "run again"
};

// The progress of the `reference` stage's computation (one per process): the window can
// draw it and request a cancel; the stage resets it when a computation starts.
ReferenceProgress& referenceStageProgress();

// Relative origin offset (see "Origin" above; shared with raster4d's shaders).
inline constexpr float kRelativeEpsilon = float(REFERENCE_RELATIVE_OFFSET);
// The smallest offset: kRelativeEpsilon x 0.1 x the occluders' diagonal (world units).
float referenceMinimumOffset(const Scene& scene);
// The offset at p (world units).
float referenceOriginOffset(const struct ReferenceRequest& request, const glm::vec3& p);

class ReferenceTracer {
public:
  // Builds the Embree scene of every non-receiver-only triangle (robust, high quality).
  explicit ReferenceTracer(const Scene& scene);
  ~ReferenceTracer();
  ReferenceTracer(const ReferenceTracer&) = delete;
  ReferenceTracer& operator=(const ReferenceTracer&) = delete;

  size_t occluderTriangles() const { return triangles_; }
  // Rays handed to Embree so far by this tracer (every call, every thread): what the cost
  // estimate (reference_cost.h) counts, less the samples behind a tangent plane.
  std::uint64_t raysCast() const;
  // 16, 8, 4 or 1: the widest packet native to this CPU ($PENUMBRA_REFERENCE_PACKET forces
  // one, for measurements; every width gives the same bits).
  int packetWidth() const { return packetWidth_; }

  // Visibility per pixel (GL order, 1 where there is no geometry). Tiles of kTile x kTile
  // pixels are shared out to `threads` std::threads (0: hardware concurrency); before each
  // tile, a cancel (progress->cancel, or the run's: core/run_control.h) stops the work, so
  // it stops within one tile's time (m^2 x 256 rays) whatever the image size. Returns false
  // (and a partial image) when cancelled. Deterministic: no result depends on the thread count.
  static constexpr int kTile = 16;
  bool trace(const ReferenceRequest& request, std::vector<float>& visibility,
             ReferenceProgress* progress = nullptr, int threads = 0) const;

  // Seconds the full image would take, timed on every `stride`-th covered pixel.
  double estimateSeconds(const ReferenceRequest& request, int stride = 97) const;

  // Visibility of one point (tests, the inspector): the same code as trace().
  float pointVisibility(const ReferenceRequest& request, const glm::vec3& wsPosition,
                        const glm::vec3& wsNormal, int pixelX, int pixelY) const;

  // Per light sample k = row * m + column of pointVisibility's rays: 1 where the sample does
  // not reach the point (hidden, or behind its tangent plane). For exact methods' tests.
  std::vector<std::uint8_t> blockedSamples(const ReferenceRequest& request,
                                           const glm::vec3& wsPosition, const glm::vec3& wsNormal,
                                           int pixelX, int pixelY) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  size_t triangles_ = 0;
  int packetWidth_ = 1;
};

// Light sample k (0 .. m*m-1) of pixel (x, y) in [0,1)^2 over the light.
glm::vec2 referenceSampleUnit(int x, int y, int k, int samplesPerSide, bool stratified);

// Prints a progress bar to stderr until progress says every row is done (call from the
// thread that waits): "\r" updates on a terminal, a start and an end line otherwise.
class TerminalProgress {
public:
  TerminalProgress(std::string label, const ReferenceProgress& progress);
  void update();   // redraws if due
  void finish(double seconds, bool cancelled);

private:
  std::string label_;
  const ReferenceProgress& progress_;
  bool terminal_;
  double lastDraw_ = -1;
  double started_;
};

// The GPU side of stage `raster4d` (raster4d.cpp): the layouts of
// stages/raster4d/raster4d/raster4d_layout.h seen from C++ and checked, the occluder triangles as one
// storage buffer, and the small helpers the passes share.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "gl/gl_texture.h"
#include "gl/gpu_layout.h"
#include "scene/scene.h"

namespace gpu {
#include "raster4d/raster4d/raster4d_layout.h"
}  // namespace gpu

static_assert(offsetof(gpu::Raster4dParams, lsFromWorld) == 0);
static_assert(offsetof(gpu::Raster4dParams, light) == 64);
static_assert(offsetof(gpu::Raster4dParams, plane) == 80);
static_assert(offsetof(gpu::Raster4dParams, fb) == 96);
static_assert(offsetof(gpu::Raster4dParams, sizes) == 112);
static_assert(offsetof(gpu::Raster4dParams, band) == 128);
static_assert(offsetof(gpu::Raster4dParams, modes) == 144);
static_assert(offsetof(gpu::Raster4dParams, pick) == 160);
static_assert(offsetof(gpu::Raster4dParams, dispatch) == 176);
static_assert(offsetof(gpu::Raster4dParams, options) == 192);
static_assert(offsetof(gpu::Raster4dParams, budget) == 208);
static_assert(sizeof(gpu::Raster4dParams) == 224);
static_assert(offsetof(gpu::Raster4dState, plane) == 48 && offsetof(gpu::Raster4dState, fb) == 64);
static_assert(sizeof(gpu::Raster4dState) == 80);
static_assert(sizeof(gpu::Raster4dPlan) == 32);
static_assert(offsetof(gpu::Raster4dBandPlan, dispatch) == 16 &&
              offsetof(gpu::Raster4dBandPlan, samplesCommand) == 32 &&
              offsetof(gpu::Raster4dBandPlan, trianglesCommand) == 48);
static_assert(sizeof(gpu::Raster4dBandPlan) == 64);
// Every pass within GL 4.5's minimum of 8 storage blocks per compute shader.
static_assert(gpu::distinctBelow({R4D_RECEIVERS_RECEIVERS, R4D_RECEIVERS_STATE}, gpu::kStorageBindings));
static_assert(gpu::distinctBelow({R4D_PLACE_STATE}, gpu::kStorageBindings));
static_assert(gpu::distinctBelow({R4D_PLAN_SAMPLE_COUNTS, R4D_PLAN_TRIANGLE_COUNTS,
                                  R4D_PLAN_SAMPLE_STARTS, R4D_PLAN_TRIANGLE_STARTS, R4D_PLAN_STATE,
                                  R4D_PLAN_PLAN, R4D_PLAN_STEP5_COMMANDS}, gpu::kStorageBindings));
static_assert(gpu::distinctBelow({R4D_SAMPLES_RECEIVERS, R4D_SAMPLES_COUNTS, R4D_SAMPLES_STARTS,
                                  R4D_SAMPLES_CURSORS, R4D_SAMPLES_LIST}, gpu::kStorageBindings));
static_assert(gpu::distinctBelow({R4D_TRIANGLES_TRIANGLES, R4D_TRIANGLES_LS_TRIANGLES,
                                  R4D_TRIANGLES_BOXES, R4D_TRIANGLES_STATE, R4D_TRIANGLES_COUNTS,
                                  R4D_TRIANGLES_STARTS, R4D_TRIANGLES_CURSORS, R4D_TRIANGLES_LIST},
                                 gpu::kStorageBindings));
static_assert(gpu::distinctBelow({R4D_SCAN_COUNTS, R4D_SCAN_STARTS}, gpu::kStorageBindings));
static_assert(gpu::distinctBelow({R4D_OCCLUSION_RECEIVERS, R4D_OCCLUSION_LS_TRIANGLES,
                                  R4D_OCCLUSION_BOXES, R4D_OCCLUSION_SAMPLE_LIST,
                                  R4D_OCCLUSION_TRIANGLE_STARTS, R4D_OCCLUSION_TRIANGLE_LIST,
                                  R4D_OCCLUSION_MASKS, R4D_OCCLUSION_CELL_PAIRS},
                                 gpu::kStorageBindings));
static_assert(gpu::distinctBelow({R4D_RESOLVE_RECEIVERS, R4D_RESOLVE_MASKS}, gpu::kStorageBindings));
static_assert(gpu::distinctBelow({R4D_CELLS_TRIANGLE_COUNTS, R4D_CELLS_SAMPLE_COUNTS,
                                  R4D_CELLS_PAIRS}, gpu::kStorageBindings));
static_assert(gpu::distinctBelow({FRAME_BLOCK_BINDING, LIGHT_BLOCK_BINDING, RASTER4D_PARAMS_BINDING},
                                 gpu::kUniformBindings));

// The occluders (every triangle of the objects that are not receiver-only, the set the
// reference traces), three world-space vec4 per triangle, uploaded when they change.
class Raster4dOccluders {
public:
  void update(const Scene& scene);
  const GlBuffer& buffer() const { return buffer_; }
  int triangles() const { return triangles_; }

private:
  GlBuffer buffer_;
  std::string key_;
  int triangles_ = 0;
};

// Resizes `buffer` to exactly `bytes` (contents undefined) unless it already has that size.
void ensureBufferBytes(const GlBuffer& buffer, size_t bytes);
// Fills the first `bytes` of `buffer` with zeros.
void zeroBuffer(const GlBuffer& buffer, size_t bytes);
// Dispatches a program with local size 64 over `count` items (shaders/raster4d/raster4d/raster4d.glsl
// linearIndex), then waits for its writes.
void dispatchLinear(std::uint64_t count);
// Dispatches an 8x8-group program over width x height.
void dispatchGrid(int width, int height);

// Light space (stages/raster4d/raster4d/raster4d_layout.h): rows right, up, forward; origin `centre`.
glm::mat4 lightSpaceFromWorld(const glm::vec3& centre, const glm::vec3& right,
                              const glm::vec3& up, const glm::vec3& forward);

// What the CPU knows before the GPU has counted (no read-back inside the run): bounds on the
// lists' entries, hence the lists' capacities, the band slots the plan may fill and STEP 5's
// dispatches per slot (raster4d_plan.comp). For an eye of width x height, an FB of fb x fb,
// `triangles` occluders, max_entries, bands of at most maxRows rows, `chunk` list entries
// per STEP 5 chunk:
//  - entries: a sample goes to 1 FB pixel (L0) or at most fb per row and fb x fb in all
//    (proj4); a triangle to at most fb per row and fb x fb in all.
//  - a band of two or more rows holds at most max_entries of each list (its last row was
//    added only if they fit); a band of one row at most that row's entries. So a list needs
//    min(all entries, max(max_entries, one row's)).
//  - bands: those ended by maxRows are disjoint runs of maxRows rows (at most fb / maxRows);
//    one ended because the next row did not fit holds, with that row, more than max_entries
//    of a list, and each row is counted so at most twice (in its band, and as the row after
//    the band before), so there are fewer than 2 S / max_entries of them for S entries (and
//    as many for the triangles); plus the last band; and never more than fb.
//  - STEP 5's chunks: the longest list has at most `triangles` entries; one dispatch covers
//    RASTER4D_MAX_GROUPS chunks.
struct Raster4dListBounds {
  std::uint64_t sampleCapacity, triangleCapacity;
  int bandSlots, step5Commands;
};
Raster4dListBounds raster4dListBounds(int width, int height, int fb, int triangles, bool l0,
                                      std::uint64_t maxEntries, int maxRows, int chunk);

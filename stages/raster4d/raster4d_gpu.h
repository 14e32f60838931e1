// The GPU side of stage `raster4d` (raster4d.cpp): the layouts of
// shaders/shared/raster4d_layout.h seen from C++ and checked, the occluder triangles as one
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
#include "shared/raster4d_layout.h"
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
static_assert(sizeof(gpu::Raster4dParams) == 208);
static_assert(sizeof(gpu::Raster4dState) == 48);
// Every pass within GL 4.5's minimum of 8 storage blocks per compute shader.
static_assert(gpu::distinctBelow({R4D_RECEIVERS_RECEIVERS, R4D_RECEIVERS_STATE}, gpu::kStorageBindings));
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
// Dispatches a program with local size 64 over `count` items (shared/raster4d.glsl
// linearIndex), then waits for its writes.
void dispatchLinear(std::uint64_t count);
// Dispatches an 8x8-group program over width x height.
void dispatchGrid(int width, int height);

template <typename T>
std::vector<T> readBuffer(const GlBuffer& buffer, size_t count, size_t first = 0) {
  std::vector<T> values(count);
  if (count) glGetNamedBufferSubData(buffer.id(), GLintptr(first * sizeof(T)), GLsizeiptr(count * sizeof(T)), values.data());
  return values;
}

// Light space (shaders/shared/raster4d_layout.h): rows right, up, forward; origin `centre`.
glm::mat4 lightSpaceFromWorld(const glm::vec3& centre, const glm::vec3& right,
                              const glm::vec3& up, const glm::vec3& forward);

// The rows [first, end) of one band of FB rows (tiles when the lists do not fit at once).
struct Raster4dBand {
  int firstRow, endRow;
  std::uint32_t sampleBase, sampleEntries, triangleBase, triangleEntries;
};
// Splits the FB rows into bands of at most `maxRows` rows whose sample and triangle entries
// each fit in `maxEntries` (a single row that does not fit gets a band of its own): from the
// prefix sums of the counts (size fbWidth * fbHeight + 1).
std::vector<Raster4dBand> planBands(const std::vector<std::uint32_t>& sampleStarts,
                                    const std::vector<std::uint32_t>& triangleStarts,
                                    int fbWidth, int fbHeight, std::uint64_t maxEntries,
                                    int maxRows);

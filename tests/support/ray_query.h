// Runs the GLSL searches of the trace stage (shaders/tests/ray_query.comp) on given rays
// through given layers, so tests can hold them against the CPU oracles.
#pragma once
#include <glm/glm.hpp>

#include <vector>

#include "gl/gl_texture.h"
#include "gl/gpu_layout_ray_query.h"
#include "gl/gpu_layout_trace.h"

struct RayQueryOutcome {
  bool blocked;
  unsigned fetches, iterations;
};

class RayQueryRunner {
public:
  // Layers in GL order (row 0 = v 0), linear light depth; zNear/zFar as in frame_block.h.
  RayQueryRunner(int width, int height, const std::vector<float>& nearLayer,
                 const std::vector<float>& farLayer, float zNear, float zFar);
  // search: SEARCH_*; layers: 1 or 2. Each query: A, B (texels), zA, zB, sStart, sEnd.
  std::vector<RayQueryOutcome> run(const std::vector<gpu::RayQuery>& queries, int search,
                                   int layers, float linearStep = 1.0f, int binarySteps = 6,
                                   int maxIterations = 4096);
  int levelCount() const { return levels_.layers(); }
  // Which hierarchy the searches read (HIERARCHY_*; both are built): N-buffer by default.
  void useHierarchy(int hierarchy) { hierarchy_ = hierarchy; }

private:
  int width_, height_;
  float zNear_, zFar_;
  int hierarchy_ = HIERARCHY_NBUFFER;
  GlTexture near_, far_, levels_, minmax_;
};

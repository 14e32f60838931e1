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
  unsigned earlyOutFetches = 0;       // the early outs' share of `fetches`
  unsigned ended = RAY_QUERY_SEARCHED;  // RAY_QUERY_*: an early out, or the search
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
  // The trace stage's early outs before the search (shortening off; ray_query.comp):
  // bit 0 the region test, bit 1 the inside test; 0 (default): the search alone.
  void useEarlyOuts(int bits) { earlyOuts_ = bits; }

private:
  int width_, height_;
  float zNear_, zFar_;
  int hierarchy_ = HIERARCHY_NBUFFER;
  int earlyOuts_ = 0;
  GlTexture near_, far_, levels_, minmax_;
};

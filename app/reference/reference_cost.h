// What a reference image costs, estimated before it is traced (docs/decisions/061-cost-
// estimates-raster4d-reference.md): the rays are exactly every light sample of every
// covered pixel, m^2 per receiver (a sample behind the receiver's tangent plane is skipped
// unlit, so the rays actually traced are at most this), and each ray walks Embree's BVH,
// whose depth grows as log2 of the occluder triangles. The work is their product, in "ray
// steps": rays x (1 + log2(1 + occluder triangles)).
#pragma once
#include <cstddef>

#include "reference/reference_trace.h"

struct ReferenceCostEstimate {
  double rays = 0;      // covered pixels x m^2
  double bvhDepth = 0;  // 1 + log2(1 + occluder triangles)
  double steps = 0;     // rays x bvhDepth: what reference.budget bounds (in millions)
};

ReferenceCostEstimate estimateReferenceCost(const ReferenceRequest& request,
                                            size_t occluderTriangles);

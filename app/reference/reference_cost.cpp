#include "reference/reference_cost.h"

#include <cmath>

ReferenceCostEstimate estimateReferenceCost(const ReferenceRequest& request,
                                            size_t occluderTriangles) {
  ReferenceCostEstimate estimate;
  const size_t pixels = size_t(request.width) * size_t(request.height);
  double covered = 0;
  for (size_t i = 0; i < pixels && 4 * i + 3 < request.wsPosition.size(); ++i)
    covered += request.wsPosition[4 * i + 3] > 0;
  const double m = request.samplesPerSide;
  estimate.rays = covered * m * m;
  estimate.bvhDepth = 1.0 + std::log2(1.0 + double(occluderTriangles));
  estimate.steps = estimate.rays * estimate.bvhDepth;
  return estimate;
}

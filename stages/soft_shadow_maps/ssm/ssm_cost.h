// What a soft-shadow-map run costs, estimated from the scene before the micro-patches are
// drawn (Atty et al. 2006 §3.3, §4.2.3: the cost is the number of micro-patches times the
// texels each one's quad covers in the soft shadow map, "the penumbra extent"). A micro-patch
// at light depth z_o (from the projection point; z_L the light plane, z_v the farthest
// receiver) covers a quad whose side, as a fraction of the map, is
//     z_L (z_v - z_o) / ((z_o - z_L) z_v)          (ssm_patch.glsl, penumbraRectAt)
// plus the patch's own texel: it grows without bound as an occluder approaches the light
// plane, up to the whole map. At resolution n there are up to n^2 patches of up to n^2 texels
// each: n^4 fragments, 1.1e12 at n = 1024 with an occluder next to the light.
#pragma once
#include <vector>

#include "scene/light_frame.h"
#include "scene/scene.h"

struct SsmCostEstimate {
  double fragments = 0;   // blended fragments of the patch quads, every pass
  double patches = 0;     // occluder texels that become micro-patches (front pass)
  double meanQuadTexels = 0;  // texels per quad, averaged over the patches
};

// The occluder and receiver maps rasterized on the CPU at 64 x 64 cells (cell centres,
// one cell for a triangle that covers no centre), the farthest receiver depth taken over the
// map as the GPU takes it, then the sum above over the occluder cells at resolution `n`:
// built once, evaluated at any resolution (`auto` weighs several: auto_ssm.h).
class SsmCostModel {
public:
  SsmCostModel(const Scene& scene, const LightFrame& light);
  SsmCostEstimate at(int n, int passes, double fill) const;

private:
  static constexpr int kCells = 64;
  float zNear_ = 0, farthestReceiver_ = 0;
  std::vector<float> nearest_, farthest_;  // per occluder cell
};

SsmCostEstimate estimateSsmCost(const Scene& scene, const LightFrame& light, int n, int passes,
                                double fill);

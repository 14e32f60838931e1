// Random near/far layers for ray-tracing tests (thesis §3.3): everything a real pair of
// layers contains, on purpose, in one small map.
#pragma once
#include <cstdint>

#include "support/layer_oracle.h"

struct RandomLayerOptions {
  int bumps = 6;       // smooth solids: near dips in a Gaussian, far bulges back; unioned
  int plateaus = 4;    // axis-aligned boxes with constant near/far (sharp edges)
  int sheets = 3;      // thin plates: near == far exactly (overwrite their rectangle)
  int holes = 2;       // empty rectangles: near 1, far 0 (cleared, overwrite)
  float bothFraction = 0.01f;  // scattered "both" texels: near > far but not cleared
  float minDepth = 0.05f, maxDepth = 0.95f;  // every stored solid lies in this lsDepth range
};

// Deterministic for a seed. Values are lsDepth in [0, 1]; empty texels are near 1, far 0.
LayerMaps randomLayers(int width, int height, uint32_t seed, const RandomLayerOptions& options = {});

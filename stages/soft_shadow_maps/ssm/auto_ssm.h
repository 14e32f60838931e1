// `auto` for ssm.resolution (the default; docs/decisions/136-auto-ssm-resolution.md).
//
// Soft shadow maps sample the occluders and the receivers at the map's texels (Atty et al.
// 2006 §3.2, §4.2.1): a penumbra narrower than a texel or two becomes a step, which is where
// SSM loses at contact (a plate 0.06 above the ground: a 0.02-wide penumbra inside one
// 0.054-wide texel at 128^2). The map shares the light's frustum (Eq 3.1 of the thesis), so a
// penumbra w wide at depth z spans w / (2 z tan(fov / 2)) texels per unit of resolution, the
// quantity the auto policy's edge probes already measure (auto_settings.h steps 1-2).
//
// 1. The need (called from the auto policy, chooseAutoSettings): the resolution on which the
//    penumbrae holding 98% of the penumbra area in view span kSsmPenumbraTexels texels, as
//    the light's map is chosen (decision 043), multiples of 128 in [128, 1024] (128 is the
//    old fixed default: auto never goes below it; 1024 the parameter's range).
// 2. The cost (called from the ssm stage, which knows its passes and budget): the largest of
//    those multiples (then 64, 32, 16), at most the need, whose micro-patch fragments
//    (ssm_cost.h, estimated from the scene before drawing) stay within kSsmAutoFragments and
//    ssm.budget. The cost
//    grows with the 4th power of the resolution where the penumbrae are wide (each
//    micro-patch's quad spans the penumbra in texels): a light close to the occluders keeps
//    auto at a small map instead of a run of minutes (decision 065).
#pragma once
#include <string>
#include <vector>

#include "scene/light_frame.h"
#include "scene/scene.h"

class SsmCostModel;

inline constexpr double kSsmPenumbraTexels = 4.0;
inline constexpr int kSsmAutoMin = 128, kSsmAutoMax = 1024;
// Milliseconds of blending on a GPU, under a second on llvmpipe (decision 065: 2.5e7-8e7
// fragments per second there), so that `auto` never makes SSM the slow stage of a run.
inline constexpr double kSsmAutoFragments = 2e7;

struct SsmResolutionNeed {
  int resolution = kSsmAutoMin;  // the need, a multiple of 128 in [128, 1024]
  double exact = 0;              // before rounding and clamping (0: no probe)
  double narrowestTexelsPerUnit = 0;  // the 2nd area-weighted percentile: texels per unit resolution
};

// From the probes' penumbra widths in texels per unit resolution and the penumbra area each
// stands for (any unit). No probe: the old default, 128.
SsmResolutionNeed ssmResolutionNeeded(const std::vector<double>& texelsPerResolution,
                                      const std::vector<double>& areas);

struct SsmResolutionChoice {
  int resolution = kSsmAutoMin;
  double estimatedFragments = 0;  // at that resolution
  std::string reason;             // one sentence for Frame::autoReasons
};

// budgetMillions: ssm.budget (0: no limit, then kSsmAutoFragments alone bounds it).
SsmResolutionChoice chooseSsmResolution(const SsmResolutionNeed& need, const SsmCostModel& cost,
                                        int passes, double budgetMillions);

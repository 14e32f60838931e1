#include "soft_shadow_maps/ssm/auto_ssm.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "soft_shadow_maps/ssm/ssm_cost.h"
#include "shared_inputs/weighted_percentile.h"

SsmResolutionNeed ssmResolutionNeeded(const std::vector<double>& texelsPerResolution,
                                      const std::vector<double>& areas) {
  SsmResolutionNeed need;
  if (texelsPerResolution.empty()) return need;
  need.narrowestTexelsPerUnit = weightedPercentile(texelsPerResolution, areas, 0.02);
  need.exact = kSsmPenumbraTexels / std::max(need.narrowestTexelsPerUnit, 1e-9);
  need.resolution = int(std::clamp(std::ceil(need.exact / 128.0) * 128.0, double(kSsmAutoMin),
                                   double(kSsmAutoMax)));
  return need;
}

SsmResolutionChoice chooseSsmResolution(const SsmResolutionNeed& need, const SsmCostModel& cost,
                                        int passes, double budgetMillions) {
  const double limit = budgetMillions > 0 ? std::min(kSsmAutoFragments, budgetMillions * 1e6)
                                          : kSsmAutoFragments;
  SsmResolutionChoice choice;
  int overBudget = 0;  // the smallest multiple of 128 that was too expensive
  double overFragments = 0;
  // Multiples of 128 down to 128, then halves down to 16 (the parameter's minimum): the need
  // never asks below 128, the cost may.
  for (int n = need.resolution; n >= 16; n = n > kSsmAutoMin ? n - 128 : n / 2) {
    const double fragments = cost.at(n, passes, 1.0).fragments;
    if (fragments <= limit || n == 16) {
      choice.resolution = n;
      choice.estimatedFragments = fragments;
      break;
    }
    overBudget = n;
    overFragments = fragments;
  }
  char text[480];
  if (need.exact <= 0 && overBudget == 0)
    std::snprintf(text, sizeof text,
                  "ssm %d: no occluder's penumbra falls in view (the fixed default)",
                  choice.resolution);
  else if (need.exact <= 0)
    std::snprintf(text, sizeof text,
                  "ssm %d, not the default %d (no occluder's penumbra falls in view): at %d the "
                  "micro-patches would blend about %.2g fragments, over the %.2g auto allows "
                  "(ssm_cost.h); %d blends about %.2g",
                  choice.resolution, need.resolution, overBudget, overFragments, limit,
                  choice.resolution, choice.estimatedFragments);
  else if (overBudget == 0)
    std::snprintf(text, sizeof text,
                  "ssm %d: 98%% of the penumbra area in view spans at least %.0f SSM texels "
                  "(it needs %.0f%s); about %.2g micro-patch fragments",
                  choice.resolution, kSsmPenumbraTexels, need.exact,
                  need.exact > kSsmAutoMax ? ", more than the 1024 limit" : "",
                  choice.estimatedFragments);
  else
    std::snprintf(text, sizeof text,
                  "ssm %d, not the %d that would give 98%% of the penumbra area %.0f SSM texels: "
                  "at %d the micro-patches would blend about %.2g fragments, over the %.2g "
                  "auto allows (ssm_cost.h); %d blends about %.2g",
                  choice.resolution, need.resolution, kSsmPenumbraTexels, overBudget,
                  overFragments, limit, choice.resolution, choice.estimatedFragments);
  choice.reason = text;
  return choice;
}

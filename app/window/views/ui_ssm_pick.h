// Connects the window's pick to the soft-shadow-map stage's picked views (Atty et al. 2006
// §3.4, §4.1.2): a picked eye pixel becomes ssm.pick_x / pick_y (the pickedLight view shows
// that receiver's back-projected micro-patches on the light), a pick in one of ssm's light-
// space maps (resolution x resolution, when that is not the eye size) becomes
// ssm.patch_x / patch_y (the pickedFootprint view shows that micro-patch's quad).
// Without an ssm stage it does nothing.
#pragma once

class UiState;

void pickSoftShadowMapTexels(UiState& state);

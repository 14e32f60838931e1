// Connects a pick in a stage's own light-space maps to that stage's picked map texel: every
// stage with kCapabilityPicksMapTexel (app/core/stage.h; ssm, Atty et al. 2006 §3.4, §4.1.2)
// gets patch_x / patch_y when the pick lies in a view of its `resolution` x `resolution`
// maps (and that is not the eye size; eye picks are recordPickedPixel's, ui_trace_source.h).
// ssm's pickedFootprint view shows that micro-patch's quad. Without such a stage it does
// nothing.
#pragma once

class UiState;

void pickStageMapTexels(UiState& state);

// What an annotated view PNG says below the image (app/figures/annotate.h): the view's
// colour bar (its range and colormap, labelled with the output and channel shown), the
// legend of a categorical mask (names from the output's doc, shares counted here), and the
// caption line: scene, output, texture size and the changed parameters of the producing
// stage and of every stage it depends on.
#pragma once
#include <string>
#include <vector>

#include "figures/annotate.h"

class UiState;
struct ViewPanel;

// "cube · trace.visibility · 640x480 · rays=4, sampling=random, light.resolution=256"
std::string viewCaption(const UiState& state, const ViewPanel& view);
// `values`: the shown texture's level as the view reads it.
Annotation viewAnnotation(const UiState& state, const ViewPanel& view,
                          const std::vector<float>& values, int channelCount);

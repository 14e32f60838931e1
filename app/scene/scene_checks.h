// Configurations the depth-map methods cannot represent, found from the scene alone (on
// the CPU, before any rendering) and reported as warnings by the command line and the
// window's status line, so that a method showing "no shadow" is never silently wrong:
// - the light faces away from every occluder: the light's depth layers (thesis §3.3, near
//   plane = the light's plane, Eq 3.1) hold nothing, so hard_shadow, classify and trace show
//   no shadow anywhere, while the reference (which lights both sides) shows shadows;
// - an occluder crosses the light's rectangle or encloses the light's centre: the layers
//   clip it at the light's plane, so those methods show less shadow than the reference;
// - a receiver lies in the light's plane or is cut by the light's rectangle (a light at the
//   height of the ground): part of the light is behind that surface, which the reference
//   shadows and the depth-map methods and SSM do not (they show more light).
#pragma once
#include <string>
#include <vector>

#include "scene/scene.h"

std::vector<std::string> lightWarnings(const Scene& scene);

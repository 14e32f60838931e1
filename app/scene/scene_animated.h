// The built-in animated scenes (scene/animation.h): what the papers show moving.
//   dragon_turntable  the dragon turning once every 8 s on the ground, the wall behind it
//                     (the thesis's "fully dynamic scenes"; Wang's moving geometry);
//   light_sweep       the elongated cube under a light that sweeps across it and grows from
//                     0.4 to 2.4 wide and back (Atty's "dynamic area light sources"; the
//                     penumbra widens and the classification follows it);
//   toys              several objects moving at once, after Wang et al.'s Toys: a box
//                     spinning, a ball bouncing, a ball circling, a plank rocking;
//   slow_slide        a plate sliding 0.25 and turning 5 degrees in 4 s, and back: slow
//                     enough that a coarse map's texels crawl (thesis §4.1's temporal
//                     aliasing; docs/temporal.md).
#pragma once
#include <string>
#include <vector>

#include "scene/scene.h"

std::vector<std::string> animatedSceneNames();
bool isAnimatedScene(const std::string& name);
// Throws InputError for an unknown name (or the dragon's glTF problem).
Scene makeAnimatedScene(const std::string& name, std::vector<std::string>& warnings);

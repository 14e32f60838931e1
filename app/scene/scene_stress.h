// Numerically hard scenes (issue: "test numerical stability on hard cases"), loadable by
// name like the built-ins: grazing light, contact, zero-thickness sheet, light almost
// touching an occluder, receiver far behind the occluders, geometry outside the frustum.
#pragma once
#include <string>
#include <vector>

#include "scene/scene.h"

std::vector<std::string> stressSceneNames();
bool isStressScene(const std::string& name);
Scene makeStressScene(const std::string& name);  // throws for unknown names

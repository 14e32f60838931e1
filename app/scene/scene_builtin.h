// Built-in scenes are code (docs/design.md#scenes). `cube` is the default.
#pragma once
#include <string>
#include <vector>

#include "scene/scene.h"

std::vector<std::string> builtinSceneNames();
bool isBuiltinScene(const std::string& name);
// Throws std::runtime_error naming the valid scenes, or the glTF problem for `engine`.
Scene makeBuiltinScene(const std::string& name);
// A built-in name, or a path to a scene JSON (.json) or a glTF file (.gltf/.glb) placed on a
// ground plane under a default light. Warnings from loading are appended to `warnings`.
Scene loadScene(const std::string& nameOrPath, std::vector<std::string>& warnings);

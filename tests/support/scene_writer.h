// Test support: scene JSON and glTF files written into a TempDirectory (unique, removed after),
// for the tests of bad and extreme input (tests/scene/test_scene_limits.cpp, tests/cli).
#pragma once
#include <nlohmann/json.hpp>

#include "support/temp_directory.h"

#include <filesystem>
#include <string>
#include <vector>

// A scene JSON: a 20 x 20 ground at y = 0, one occluder quad (size 1.5 at y = 1, casting
// shadows), a 1 x 1 light at (0, 4, 0) facing down, a camera looking at the origin. Tests
// edit the JSON before writing it.
nlohmann::json groundAndPlateScene();

// A glTF whose one mesh (`trianglesPerMesh` triangles, non-indexed, float positions in a
// .bin) is instanced by a tree of nodes: `fanout` nodes per level over `levels` levels of
// grouping nodes, `leaves` mesh nodes at the bottom: fanout^levels * leaves instances from
// a file of a few KiB (a "node bomb"). Returns the .gltf path.
std::string writeInstancedGltf(const TempDirectory& dir, const std::string& name, int levels,
                               int fanout, int leaves, int trianglesPerMesh,
                               const std::string& version = "2.0", double leafScale = 1.0);

// glTF 2.0 (.gltf / .glb) import into world-space SceneObjects.
// Files are untrusted input: every index, byte range and value is checked here rather
// than trusting tinygltf, and a broken file is refused with a message, never a crash.
#pragma once
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

#include "scene/gltf_animation.h"

// Loads every triangle primitive reachable from the file's default scene (or scene 0, or
// every root node when the file has no scenes), one SceneObject per primitive instance,
// with positions and normals transformed by worldFromFile * (node transforms).
// Repairable problems (bad normals, non-triangle primitives, ignored features) are
// appended to `warnings`; anything else throws InputError("<path>: <problem>"). What is
// loaded counts against `budget` (the scene's; a whole budget when null). With `animation`,
// the file's first node animation is read into it (scene/gltf_animation.h); without, the
// file's animations are not read.
std::vector<SceneObject> loadGltf(const std::string& path, const glm::mat4& worldFromFile,
                                  std::vector<std::string>& warnings, SceneBudget* budget = nullptr,
                                  GltfAnimation* animation = nullptr);
// The same from bytes already in memory (the fuzzing harness, tests/fuzz/); `path` names
// the file in messages, gives the format by its extension and the directory of external
// buffers.
std::vector<SceneObject> loadGltfFromMemory(const std::vector<unsigned char>& bytes,
                                            const std::string& path, const glm::mat4& worldFromFile,
                                            std::vector<std::string>& warnings,
                                            SceneBudget* budget = nullptr,
                                            GltfAnimation* animation = nullptr);

// The scene JSON format (assets/scenes/README.md): glTF models and ground quads placed in
// the world, one area light, one camera. Strict on purpose: a typo in a key is an error
// naming the key and the valid ones, not a silently ignored setting.
#pragma once
#include "scene/scene.h"

#include <string>
#include <vector>

// Loads and validates a scene file; relative glTF paths are relative to the file.
// Throws std::runtime_error("<path>: <json pointer>: <problem>") on any malformed input
// and "<path>: <problem>" when the assembled scene fails validateScene().
// Repairable problems (bad normals in a model, a non-orthogonal light frame) are
// appended to `warnings`.
Scene loadSceneFile(const std::string& path, std::vector<std::string>& warnings);

// The same from the file's text (the fuzzing harness, tests/fuzz/); `path` names it in
// messages and gives the directory of relative glTF paths.
Scene parseSceneFile(const std::string& text, const std::string& path,
                     std::vector<std::string>& warnings);

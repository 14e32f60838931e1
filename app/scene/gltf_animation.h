// glTF 2.0 node animations (§3.11): translation, rotation and scale channels with LINEAR or
// STEP samplers, read into ObjectMotions (scene/animation.h) for the objects the importer
// made (app/scene/scene_gltf.h). The file's first animation plays; others are named in a
// warning. CUBICSPLINE samplers and sparse or integer keyframe data are refused; morph-
// target weight channels are ignored with a warning (morph targets and skins are, too).
// Messages are "<file>: <JSON pointer into the glTF>: <problem>".
#pragma once
#include <glm/glm.hpp>

#include <string>
#include <vector>

#include "scene/animation.h"

namespace tinygltf {
class Model;
}

struct GltfAnimation {
  std::vector<ObjectMotion> motions;  // objects: indices into the loaded objects
  std::string name;                   // the animation's, or "" (none or unnamed)
};

// `objectNodePaths[i]`: the nodes from a root down to the node of loaded object i; the
// object's mesh was placed by worldFromFile * (their rest transforms).
GltfAnimation readGltfAnimation(const tinygltf::Model& model,
                                const std::vector<std::vector<int>>& objectNodePaths,
                                const glm::dmat4& worldFromFile, const std::string& path,
                                std::vector<std::string>& warnings);

// Moves a motion read for objects placed by worldFromFile to objects then transformed by
// `place` (a scene that scales a model onto its ground): pose' = place * pose * place^-1.
void placeMotion(ObjectMotion& motion, const glm::dmat4& place);

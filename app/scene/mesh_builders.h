// Procedural meshes for the built-in scenes, in world space.
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"

// Axis-aligned box of the given size centred at the origin, then transformed.
Mesh makeBox(const glm::vec3& size, const glm::mat4& worldFromLocal);
// UV sphere.
Mesh makeSphere(const glm::vec3& center, float radius, int slices = 32, int stacks = 16);
// A square of side `size` in the local xz plane (normal +y), then transformed. Zero
// thickness: both light layers see it at the same depth (near == far).
Mesh makeQuad(float size, const glm::mat4& worldFromLocal);
// Applies `worldFromLocal` to positions and (inverse transpose) normals.
void transformMesh(Mesh& mesh, const glm::mat4& worldFromLocal);

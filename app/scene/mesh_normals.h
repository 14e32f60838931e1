// Normals and transforms of triangle meshes, shared by the glTF importer and the animation
// poses: area-weighted face normals, flat normals, repaired normals, a mesh moved by a matrix.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

// Unnormalized face normal of a triangle, so that summing them weights by area.
glm::dvec3 faceNormal(const Mesh& mesh, size_t triangle);
// n normalized, or `fallback` where n has no direction (zero or not finite).
glm::vec3 unitOr(const glm::dvec3& n, const glm::vec3& fallback);
// Flat normals (glTF's rule for a primitive without normals): one vertex per corner.
void makeFlatNormals(Mesh& mesh);
// Replaces each normal flagged in `bad` by the area-weighted normal of the faces around it.
void repairNormals(Mesh& mesh, const std::vector<char>& bad);
// Positions by m, normals by its inverse transpose; a mirroring m flips the winding back.
void transformMesh(Mesh& mesh, const glm::dmat4& m);

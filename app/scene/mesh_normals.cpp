#include "scene/mesh_normals.h"

#include <cmath>
#include <cstdint>
#include <utility>

glm::dvec3 faceNormal(const Mesh& mesh, size_t triangle) {
  const glm::dvec3 a = mesh.positions[mesh.indices[3 * triangle]];
  const glm::dvec3 b = mesh.positions[mesh.indices[3 * triangle + 1]];
  const glm::dvec3 c = mesh.positions[mesh.indices[3 * triangle + 2]];
  return glm::cross(b - a, c - a);
}

glm::vec3 unitOr(const glm::dvec3& n, const glm::vec3& fallback) {
  const double length = glm::length(n);
  return length > 0 && std::isfinite(length) ? glm::vec3(n / length) : fallback;
}

void makeFlatNormals(Mesh& mesh) {
  Mesh flat;
  flat.positions.reserve(mesh.indices.size());
  flat.normals.reserve(mesh.indices.size());
  flat.indices.reserve(mesh.indices.size());
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const glm::vec3 n = unitOr(faceNormal(mesh, t), {0, 1, 0});  // degenerate: any unit
    for (int k = 0; k < 3; ++k) {
      flat.indices.push_back(static_cast<std::uint32_t>(flat.positions.size()));
      flat.positions.push_back(mesh.positions[mesh.indices[3 * t + k]]);
      flat.normals.push_back(n);
    }
  }
  mesh = std::move(flat);
}

void repairNormals(Mesh& mesh, const std::vector<char>& bad) {
  std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0));
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const glm::dvec3 n = faceNormal(mesh, t);
    for (int k = 0; k < 3; ++k) sum[mesh.indices[3 * t + k]] += n;
  }
  for (size_t i = 0; i < mesh.normals.size(); ++i)
    if (bad[i]) mesh.normals[i] = unitOr(sum[i], {0, 1, 0});
}

void transformMesh(Mesh& mesh, const glm::dmat4& m) {
  const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(m)));
  for (glm::vec3& p : mesh.positions) p = glm::vec3(m * glm::dvec4(glm::dvec3(p), 1.0));
  for (glm::vec3& n : mesh.normals) {
    const glm::dvec3 w = normalMatrix * glm::dvec3(n);
    const double length = glm::length(w);
    // A singular pose (scaled to zero) has no surface to shade; keep the normal as it was.
    if (length > 0 && std::isfinite(length)) n = glm::vec3(w / length);
  }
  if (glm::determinant(glm::dmat3(m)) < 0)
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
      std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
}

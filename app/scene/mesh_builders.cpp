#include "scene/mesh_builders.h"

#include <cmath>
#include <glm/gtc/constants.hpp>

void transformMesh(Mesh& mesh, const glm::mat4& worldFromLocal) {
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(worldFromLocal)));
  for (glm::vec3& p : mesh.positions) p = glm::vec3(worldFromLocal * glm::vec4(p, 1));
  for (glm::vec3& n : mesh.normals) n = glm::normalize(normalMatrix * n);
}

Mesh makeBox(const glm::vec3& size, const glm::mat4& worldFromLocal) {
  Mesh mesh;
  const glm::vec3 h = 0.5f * size;
  // Each face: normal axis, and two in-plane axes ordered so the winding is counter-clockwise.
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {-1.0f, 1.0f}) {
      glm::vec3 n(0), u(0), v(0);
      n[axis] = sign;
      u[(axis + 1) % 3] = 1;
      v[(axis + 2) % 3] = 1;
      if (sign < 0) std::swap(u, v);
      const auto base = std::uint32_t(mesh.positions.size());
      for (int corner = 0; corner < 4; ++corner) {
        const float a = (corner == 1 || corner == 2) ? 1.0f : -1.0f;
        const float b = (corner >= 2) ? 1.0f : -1.0f;
        mesh.positions.push_back((n + a * u + b * v) * h);
        mesh.normals.push_back(n);
      }
      mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
  transformMesh(mesh, worldFromLocal);
  return mesh;
}

Mesh makeSphere(const glm::vec3& center, float radius, int slices, int stacks) {
  Mesh mesh;
  for (int stack = 0; stack <= stacks; ++stack) {
    const float theta = glm::pi<float>() * float(stack) / float(stacks);
    for (int slice = 0; slice <= slices; ++slice) {
      const float phi = 2.0f * glm::pi<float>() * float(slice) / float(slices);
      const glm::vec3 n{std::sin(theta) * std::cos(phi), std::cos(theta),
                        -std::sin(theta) * std::sin(phi)};
      mesh.positions.push_back(center + radius * n);
      mesh.normals.push_back(n);
    }
  }
  const auto row = std::uint32_t(slices + 1);
  for (int stack = 0; stack < stacks; ++stack)
    for (int slice = 0; slice < slices; ++slice) {
      const std::uint32_t a = stack * row + slice, b = a + row;
      mesh.indices.insert(mesh.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  return mesh;
}

Mesh makeQuad(float size, const glm::mat4& worldFromLocal) {
  Mesh mesh;
  const float h = 0.5f * size;
  mesh.positions = {{-h, 0, -h}, {-h, 0, h}, {h, 0, h}, {h, 0, -h}};
  mesh.normals.assign(4, glm::vec3(0, 1, 0));
  mesh.indices = {0, 1, 2, 0, 2, 3};
  transformMesh(mesh, worldFromLocal);
  return mesh;
}

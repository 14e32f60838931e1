// Only what shadows need (DESIGN.md §5): triangle meshes with a base colour and a
// "receiver only" flag, one rectangular area light, one camera.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // one per position, unit length
  std::vector<std::uint32_t> indices;  // triangles
  size_t triangleCount() const { return indices.size() / 3; }
};

struct SceneObject {
  std::string name;
  Mesh mesh;  // world space
  glm::vec3 baseColor{0.8f};
  bool receiverOnly = false;  // kept out of the light's depth layers (thesis §3.3)
};

struct AreaLight {
  glm::vec3 center{0, 4, 0};
  glm::vec3 forward{0, -1, 0};  // the direction the light faces (its emitting side)
  glm::vec3 up{0, 0, -1};       // in-plane direction of `height`
  float width = 1, height = 1;
};

struct Camera {
  glm::vec3 position{0, 3, 6};
  glm::vec3 target{0, 0, 0};
  glm::vec3 up{0, 1, 0};
  float fovYDegrees = 45;
};

struct Bounds {
  glm::vec3 min{1e30f}, max{-1e30f};
  void extend(const glm::vec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
  bool empty() const { return min.x > max.x; }
};

struct Scene {
  std::string name;
  std::vector<SceneObject> objects;
  AreaLight light;
  Camera camera;

  Bounds bounds(bool occludersOnly = false) const;
  size_t triangleCount() const;
};

// Checks what every consumer relies on: finite positions and normals, indices in range,
// a light with positive finite size and orthogonal frame. Returns "" or a message.
std::string validateScene(const Scene& scene);

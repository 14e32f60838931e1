// Only what shadows need (docs/design.md#scenes): triangle meshes with a base colour and a
// "receiver only" flag, one rectangular area light, one camera.
#pragma once
#include <glm/glm.hpp>

#include "scene/animation.h"

#include <cstdint>
#include <string>
#include <vector>

// Scene limits (README "Scene files"), what every back end can represent:
// - coordinates within +-kMaxCoordinate: the GPU stages compute in single precision, where
//   products of three coordinates (squared distances, projections) must stay below 3.4e38,
//   and Embree rejects rays past 1.8e18; at 1e6 they keep a wide margin;
// - a budget for the whole scene, whatever files it is made of: GpuScene keeps a vertex and
//   an index buffer per object and Embree a BVH over every occluder triangle, in memory.
constexpr double kMaxCoordinate = 1e6;
constexpr size_t kMaxSceneTriangles = 5'000'000;
constexpr size_t kMaxSceneObjects = 100'000;  // mesh instances (one draw call each)

// What is left of the budget while a scene is assembled (app/scene/scene_gltf.h).
// Bytes of glTF files and buffers read for one scene (app/scene/gltf_file_access.h).
constexpr std::uint64_t kMaxSceneFileBytes = std::uint64_t(2) << 30;

struct SceneBudget {
  size_t triangles = kMaxSceneTriangles;
  size_t objects = kMaxSceneObjects;
  std::uint64_t fileBytes = kMaxSceneFileBytes;
};

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
  // What loading did that the objects do not show, in words ("bunny.glb: file units x [...]
  // scaled by 0.0161 to 2.5 across"), for the scene summary (scene/scene_frame.h).
  std::vector<std::string> notes;
  // The objects and the light above are at rest; poseAt(scene, t) applies this
  // (scene/animation.h). Empty for a static scene.
  Animation animation;
  // The time (seconds) poseAt posed this scene at; 0 for a scene at rest.
  double time = 0;

  Bounds bounds(bool occludersOnly = false) const;
  size_t triangleCount() const;
};

// Checks what every consumer relies on: finite positions and normals, indices in range,
// a light with positive finite size and orthogonal frame, the limits above. Returns "" or
// a message naming the limit.
std::string validateScene(const Scene& scene);

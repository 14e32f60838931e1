// The scene as Embree sees it for `auto`'s analysis (stages/shared_inputs/light/auto_settings.cpp):
// every triangle of the posed scene in one level, and which geometry ids are occluders.
#pragma once

#include <embree3/rtcore.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "scene/scene.h"

// Rays this thread handed to Embree through SceneRays::hit (the probes run on several threads;
// each counts its own, and the analysis sums them).
std::uint64_t& sceneRaysOnThisThread();

// Every triangle of the scene (receivers too: the penumbra falls on them), with which
// geometry ids are occluders. One level, built from the posed triangles as they are: a new
// pose is a new build (docs/decisions/140-auto-per-pose.md: a two-level scene refitted per
// pose, or instances of each mesh at rest, would answer some rays differently).
struct SceneRays {
  RTCScene scene = nullptr;
  std::vector<bool> occluder;  // by geometry id
  explicit SceneRays(const Scene& source);
  SceneRays(const SceneRays&) = delete;
  SceneRays& operator=(const SceneRays&) = delete;
  ~SceneRays();
  // Nearest hit along origin + t direction, t in (tNear, inf): t (inf: none), geometry id and,
  // when asked, the geometric normal there.
  float hit(const glm::vec3& origin, const glm::vec3& direction, float tNear, unsigned& geometry,
            glm::vec3* normal = nullptr) const;
};

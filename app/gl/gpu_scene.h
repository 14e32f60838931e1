// The scene's triangles on the GPU: one vertex/index buffer pair per object. Every
// allocation is checked: out of memory throws (naming the object) and frees what was made.
#pragma once
#include <epoxy/gl.h>

#include <vector>

#include "scene/scene.h"

class GpuScene {
public:
  explicit GpuScene(const Scene& scene);
  ~GpuScene();
  GpuScene(const GpuScene&) = delete;
  GpuScene& operator=(const GpuScene&) = delete;

  struct DrawItem {
    GLuint vertexArray, vertexBuffer, indexBuffer;
    GLsizei indexCount;
    glm::vec3 baseColor;
    bool receiverOnly;
  };
  // Vertex attributes: location 0 = wsPosition (vec3), location 1 = wsNormal (vec3).
  // Per draw the uniform at `colorLocation` (if >= 0) receives the base colour (vec3).
  void draw(bool includeReceivers, GLint colorLocation = -1) const;
  // Only the receiver-only objects (soft shadow maps' receiver map, Atty et al. 2006 §3.1).
  void drawReceivers() const;
  const std::vector<DrawItem>& items() const { return items_; }

private:
  void upload(const Scene& scene);
  void release();
  std::vector<DrawItem> items_;
};

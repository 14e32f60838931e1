#include "gl/gpu_scene.h"

#include <string>

#include "gl/gl_texture.h"

GpuScene::GpuScene(const Scene& scene) {
  try {
    upload(scene);
  } catch (...) {
    release();  // what was created before the failure
    throw;
  }
}

void GpuScene::upload(const Scene& scene) {
  for (const SceneObject& object : scene.objects) {
    DrawItem item{};
    std::vector<float> vertices;
    vertices.reserve(object.mesh.positions.size() * 6);
    for (size_t i = 0; i < object.mesh.positions.size(); ++i) {
      const glm::vec3& p = object.mesh.positions[i];
      const glm::vec3& n = object.mesh.normals[i];
      vertices.insert(vertices.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
    }
    clearGlErrors();
    glCreateBuffers(1, &item.vertexBuffer);
    glCreateBuffers(1, &item.indexBuffer);
    glCreateVertexArrays(1, &item.vertexArray);
    items_.push_back(item);  // owned from here: released on failure
    glNamedBufferStorage(item.vertexBuffer, GLsizeiptr(vertices.size() * sizeof(float)),
                         vertices.data(), 0);
    checkGlAllocation("the vertices of '" + object.name + "'", vertices.size() * sizeof(float));
    clearGlErrors();
    glNamedBufferStorage(item.indexBuffer,
                         GLsizeiptr(object.mesh.indices.size() * sizeof(std::uint32_t)),
                         object.mesh.indices.data(), 0);
    checkGlAllocation("the indices of '" + object.name + "'",
                      object.mesh.indices.size() * sizeof(std::uint32_t));
    glVertexArrayVertexBuffer(item.vertexArray, 0, item.vertexBuffer, 0, 6 * sizeof(float));
    glVertexArrayElementBuffer(item.vertexArray, item.indexBuffer);
    for (GLuint attribute : {0u, 1u}) {
      glEnableVertexArrayAttrib(item.vertexArray, attribute);
      glVertexArrayAttribFormat(item.vertexArray, attribute, 3, GL_FLOAT, GL_FALSE,
                                attribute * 3 * sizeof(float));
      glVertexArrayAttribBinding(item.vertexArray, attribute, 0);
    }
    item.indexCount = GLsizei(object.mesh.indices.size());
    item.baseColor = object.baseColor;
    item.receiverOnly = object.receiverOnly;
    items_.back() = item;
  }
}

GpuScene::~GpuScene() { release(); }

void GpuScene::release() {
  for (DrawItem& item : items_) {
    glDeleteVertexArrays(1, &item.vertexArray);
    glDeleteBuffers(1, &item.vertexBuffer);
    glDeleteBuffers(1, &item.indexBuffer);
  }
  items_.clear();
}

void GpuScene::draw(bool includeReceivers, GLint colorLocation) const {
  for (const DrawItem& item : items_) {
    if (item.receiverOnly && !includeReceivers) continue;
    if (colorLocation >= 0) glUniform3fv(colorLocation, 1, &item.baseColor.x);
    glBindVertexArray(item.vertexArray);
    glDrawElements(GL_TRIANGLES, item.indexCount, GL_UNSIGNED_INT, nullptr);
  }
  glBindVertexArray(0);
}

void GpuScene::drawReceivers() const {
  for (const DrawItem& item : items_) {
    if (!item.receiverOnly) continue;
    glBindVertexArray(item.vertexArray);
    glDrawElements(GL_TRIANGLES, item.indexCount, GL_UNSIGNED_INT, nullptr);
  }
  glBindVertexArray(0);
}

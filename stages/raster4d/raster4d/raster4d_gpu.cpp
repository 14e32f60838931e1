#include "raster4d_gpu.h"

#include <algorithm>
#include <cmath>

#include "gl/shader_program.h"
#include "reference/reference_cache.h"

void Raster4dOccluders::update(const Scene& scene) {
  ContentHash hash;
  for (const SceneObject& object : scene.objects) {
    if (object.receiverOnly) continue;
    hash.bytes(object.mesh.positions.data(), object.mesh.positions.size() * sizeof(glm::vec3));
    hash.bytes(object.mesh.indices.data(), object.mesh.indices.size() * sizeof(std::uint32_t));
  }
  const std::string key = hash.hex();
  if (key == key_) return;
  std::vector<glm::vec4> vertices;
  for (const SceneObject& object : scene.objects) {
    if (object.receiverOnly) continue;  // casts no shadow in any method (thesis §3.3)
    for (std::uint32_t index : object.mesh.indices)
      vertices.emplace_back(object.mesh.positions[index], 1.0f);
  }
  triangles_ = int(vertices.size() / 3);
  if (vertices.empty()) vertices.emplace_back(0.0f);  // a buffer must not be empty
  buffer_.upload(vertices.data(), vertices.size() * sizeof(glm::vec4));
  key_ = key;
}

void ensureBufferBytes(const GlBuffer& buffer, size_t bytes) {
  bytes = std::max<size_t>(bytes, 16);
  GLint64 current = 0;
  glGetNamedBufferParameteri64v(buffer.id(), GL_BUFFER_SIZE, &current);
  if (size_t(current) != bytes) glNamedBufferData(buffer.id(), GLsizeiptr(bytes), nullptr, GL_DYNAMIC_DRAW);
}

void zeroBuffer(const GlBuffer& buffer, size_t bytes) {
  const std::uint32_t zero = 0;
  if (bytes) glClearNamedBufferSubData(buffer.id(), GL_R32UI, 0, GLsizeiptr(bytes), GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

void dispatchLinear(std::uint64_t count) {
  const std::uint64_t groups = (count + 63) / 64;
  if (groups == 0) return;
  const std::uint64_t x = std::min<std::uint64_t>(groups, 65535);
  glDispatchCompute(GLuint(x), GLuint((groups + x - 1) / x), 1);
  glMemoryBarrier(kBufferResults | kImageResults);
}

void dispatchGrid(int width, int height) {
  glDispatchCompute(GLuint((width + 7) / 8), GLuint((height + 7) / 8), 1);
  glMemoryBarrier(kBufferResults | kImageResults);
}

glm::mat4 lightSpaceFromWorld(const glm::vec3& centre, const glm::vec3& right,
                              const glm::vec3& up, const glm::vec3& forward) {
  glm::mat4 m(1.0f);
  const glm::vec3 axes[3] = {right, up, forward};
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 3; ++column) m[column][row] = axes[row][column];
    m[3][row] = -glm::dot(axes[row], centre);
  }
  return m;
}

Raster4dListBounds raster4dListBounds(int width, int height, int fb, int triangles, bool l0,
                                      std::uint64_t maxEntries, int maxRows, int chunk) {
  const double receivers = double(width) * double(height), cells = double(fb) * double(fb);
  const double samples = l0 ? receivers : receivers * cells;
  const double rowSamples = l0 ? receivers : receivers * double(fb);
  const double entries = double(triangles) * cells, rowEntries = double(triangles) * double(fb);
  const double most = double(maxEntries);
  auto capacity = [&](double all, double row) {
    return std::uint64_t(std::max(1.0, std::min(all, std::max(most, row))));
  };
  Raster4dListBounds bounds{};
  bounds.sampleCapacity = capacity(samples, rowSamples);
  bounds.triangleCapacity = capacity(entries, rowEntries);
  const double slots = 1.0 + std::floor(double(fb) / double(maxRows)) +
                       std::floor(2.0 * samples / most) + std::floor(2.0 * entries / most);
  bounds.bandSlots = int(std::min(double(fb), slots));
  const double chunks = std::ceil(double(triangles) / double(chunk));
  bounds.step5Commands = std::max(1, int(std::ceil(chunks / double(RASTER4D_MAX_GROUPS))));
  return bounds;
}

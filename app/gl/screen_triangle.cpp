#include "gl/screen_triangle.h"

#include <stdexcept>

ScreenTriangle::~ScreenTriangle() {
  if (vertexArray_) glDeleteVertexArrays(1, &vertexArray_);
}

void ScreenTriangle::draw(const std::vector<const GlTexture*>& targets, int layer) {
  drawRect(targets, {0, 0}, {targets.at(0)->width(), targets.at(0)->height()}, layer);
}

void ScreenTriangle::drawRect(const GlTexture& target, glm::ivec2 origin, glm::ivec2 size) {
  drawRect({&target}, origin, size, -1);
}

void ScreenTriangle::drawRect(const std::vector<const GlTexture*>& targets, glm::ivec2 origin,
                              glm::ivec2 size, int layer) {
  constexpr int kMaxTargets = 8;  // GL 4.5 guarantees 8 draw buffers
  if (targets.empty() || targets.size() > kMaxTargets)
    throw std::invalid_argument("ScreenTriangle: 1 to 8 targets");
  if (!vertexArray_) glCreateVertexArrays(1, &vertexArray_);
  GLenum buffers[kMaxTargets];
  for (int i = 0; i < kMaxTargets; ++i) {
    const GLenum attachment = GLenum(GL_COLOR_ATTACHMENT0 + i);
    const GLuint texture = i < int(targets.size()) ? targets[size_t(i)]->id() : 0;
    if (layer < 0 || texture == 0)
      glNamedFramebufferTexture(framebuffer_.id(), attachment, texture, 0);
    else
      glNamedFramebufferTextureLayer(framebuffer_.id(), attachment, texture, 0, layer);
    buffers[i] = attachment;
  }
  glNamedFramebufferDrawBuffers(framebuffer_.id(), GLsizei(targets.size()), buffers);
  framebuffer_.checkComplete("screen triangle");
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glViewport(origin.x, origin.y, size.x, size.y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  glBindVertexArray(vertexArray_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

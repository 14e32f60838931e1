#include "gl/screen_triangle.h"

#include <stdexcept>

ScreenTriangle::~ScreenTriangle() {
  if (vertexArray_) glDeleteVertexArrays(1, &vertexArray_);
}

void ScreenTriangle::draw(const std::vector<const GlTexture*>& targets, int layer) {
  std::vector<Target> layered;
  for (const GlTexture* texture : targets) layered.push_back({texture, layer});
  drawRect(layered, {0, 0}, {targets.at(0)->width(), targets.at(0)->height()});
}

void ScreenTriangle::drawLayers(const GlTexture& array, const std::vector<int>& layers) {
  std::vector<Target> layered;
  for (int layer : layers) layered.push_back({&array, layer});
  drawRect(layered, {0, 0}, {array.width(), array.height()});
}

void ScreenTriangle::clearAndDraw(const std::vector<const GlTexture*>& targets,
                                  const std::vector<glm::vec4>& clearTo) {
  if (clearTo.size() != targets.size())
    throw std::invalid_argument("ScreenTriangle: one clear value per target");
  std::vector<Target> whole;
  for (const GlTexture* texture : targets) whole.push_back({texture, -1});
  drawRect(whole, {0, 0}, {targets.at(0)->width(), targets.at(0)->height()}, clearTo);
}

void ScreenTriangle::drawRect(const std::vector<Target>& targets, glm::ivec2 origin,
                              glm::ivec2 size, const std::vector<glm::vec4>& clearTo,
                              const GlTexture* depth) {
  constexpr int kMaxTargets = 8;  // GL 4.5 guarantees 8 draw buffers
  if (targets.empty() || targets.size() > kMaxTargets)
    throw std::invalid_argument("ScreenTriangle: 1 to 8 targets");
  if (!vertexArray_) glCreateVertexArrays(1, &vertexArray_);
  GLenum buffers[kMaxTargets];
  for (int i = 0; i < kMaxTargets; ++i) {
    const GLenum attachment = GLenum(GL_COLOR_ATTACHMENT0 + i);
    const Target target = i < int(targets.size()) ? targets[size_t(i)] : Target{nullptr, -1};
    const GLuint texture = target.texture ? target.texture->id() : 0;
    if (target.layer < 0 || texture == 0)
      glNamedFramebufferTexture(framebuffer_.id(), attachment, texture, 0);
    else
      glNamedFramebufferTextureLayer(framebuffer_.id(), attachment, texture, 0, target.layer);
    buffers[i] = attachment;
  }
  glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, depth ? depth->id() : 0, 0);
  glNamedFramebufferDrawBuffers(framebuffer_.id(), GLsizei(targets.size()), buffers);
  framebuffer_.checkComplete("screen triangle");
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glViewport(origin.x, origin.y, size.x, size.y);
  if (depth) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
  } else {
    glDisable(GL_DEPTH_TEST);
  }
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  for (size_t i = 0; i < clearTo.size(); ++i)
    glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, GLint(i), &clearTo[i].x);
  glBindVertexArray(vertexArray_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  if (depth) {
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

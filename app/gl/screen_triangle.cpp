#include "gl/screen_triangle.h"

ScreenTriangle::~ScreenTriangle() {
  if (vertexArray_) glDeleteVertexArrays(1, &vertexArray_);
}

void ScreenTriangle::draw(const GlTexture& target, int layer) {
  drawRect(target, {0, 0}, {target.width(), target.height()}, layer);
}

void ScreenTriangle::drawRect(const GlTexture& target, glm::ivec2 origin, glm::ivec2 size,
                              int layer) {
  if (!vertexArray_) glCreateVertexArrays(1, &vertexArray_);
  if (layer < 0)
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
  else
    glNamedFramebufferTextureLayer(framebuffer_.id(), GL_COLOR_ATTACHMENT0, target.id(), 0, layer);
  glNamedFramebufferDrawBuffer(framebuffer_.id(), GL_COLOR_ATTACHMENT0);
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

#include "texture_view.h"

const GlTexture& TextureView::render(const GlTexture& source, const DisplayHint& hint) {
  if (display_.width() != source.width() || display_.height() != source.height())
    display_ = GlTexture(GL_RGBA8, source.width(), source.height());
  program_.use();
  glBindTextureUnit(0, source.id());
  glBindImageTexture(0, display_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  glUniform1i(0, hint.channel);
  glUniform2f(1, hint.black, hint.white);
  glUniform1i(2, int(hint.colormap));
  glUniform1i(3, source.channelCount());
  glDispatchCompute((source.width() + 7) / 8, (source.height() + 7) / 8, 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  return display_;
}

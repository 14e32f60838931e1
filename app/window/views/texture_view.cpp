#include "window/views/texture_view.h"

#include <algorithm>

#include "io/colormap.h"

// 1. The sampler type must match the texture: float / unsigned integer, 2D / 2D array.
ShaderProgram& TextureView::programFor(const GlTexture& source) {
  if (source.isInteger()) return source.isArray() ? uintArray_ : uint2D_;
  return source.isArray() ? floatArray_ : float2D_;
}

// 2. One dispatch over the layer; the display texture is reallocated only on resize.
const GlTexture& TextureView::render(const GlTexture& source, const ViewSettings& settings) {
  if (display_.width() != source.width() || display_.height() != source.height())
    display_ = GlTexture(GL_RGBA8, source.width(), source.height());
  const int channelCount = source.channelCount();
  const DisplayHint hint = toDisplayHint(settings, channelCount);
  const float range = hint.white - hint.black;
  int mask = 0;
  for (int c = 0; c < 4; ++c) mask |= settings.channels[size_t(c)] ? 1 << c : 0;
  programFor(source).use();
  glBindTextureUnit(0, source.id());
  glBindImageTexture(0, display_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  glUniform1i(0, hint.channel);
  // The scale is computed here, as app/io/colormap.cpp does, so both round the same way.
  glUniform2f(1, hint.black, range != 0 ? 1.0f / range : 0.0f);
  glUniform1i(2, int(hint.colormap));
  glUniform1i(3, channelCount);
  glUniform1i(4, mask);
  glUniform1i(5, settings.overlay ? 1 : 0);
  glUniform1i(6, std::clamp(settings.layer, 0, std::max(source.layers() - 1, 0)));
  glDispatchCompute(GLuint(source.width() + 7) / 8, GLuint(source.height() + 7) / 8, 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  return display_;
}

const GlTexture& TextureView::render(const GlTexture& source, const ViewSettings& settings,
                                     long generation) {
  const ViewSettings& s = last_.settings;
  const bool same = last_.source == source.id() && last_.generation == generation &&
                    s.channels == settings.channels && s.black == settings.black &&
                    s.white == settings.white && s.colormap == settings.colormap &&
                    s.overlay == settings.overlay && s.layer == settings.layer &&
                    display_.width() == source.width() && display_.height() == source.height();
  if (same) return display_;
  last_ = {source.id(), generation, settings};
  return render(source, settings);
}

const GlTexture& TextureView::render(const GlTexture& source, const DisplayHint& hint) {
  Output output{"", "", source.internalFormat(), {}, hint};
  return render(source, defaultViewSettings(output, source.channelCount()));
}

void TextureView::autoRange(const GlTexture& source, ViewSettings& settings, long generation) {
  if (!settings.autoRange) return;
  const int channel = singleChannel(settings, source.channelCount());
  if (channel < 0) return;
  const int layer = std::clamp(settings.layer, 0, std::max(source.layers() - 1, 0));
  RangeKey& r = range_;
  if (r.source != source.id() || r.generation != generation || r.layer != layer || r.channel != channel) {
    const std::vector<float> values = readRegion(source, 0, 0, source.width(), source.height(), layer);
    r = {source.id(), generation, layer, channel, false, 0, 1};
    r.found = robustRange(values, source.channelCount(), channel,
                          settings.colormap == Colormap::Diverging, r.low, r.high);
  }
  if (!r.found) return;
  settings.black = r.low;
  settings.white = r.high;
}

// 3. Read-back of a rectangle, in the formats GlTexture::readFloats uses.
std::vector<float> readRegion(const GlTexture& texture, int x0, int y0, int width, int height,
                              int layer) {
  // A 2D texture has one layer (a view's level slider may say more: the shown mip level).
  layer = texture.isArray() ? std::clamp(layer, 0, texture.layers() - 1) : 0;
  x0 = std::clamp(x0, 0, texture.width());
  y0 = std::clamp(y0, 0, texture.height());
  width = std::clamp(width, 0, texture.width() - x0);
  height = std::clamp(height, 0, texture.height() - y0);
  const int channels = texture.channelCount();
  const size_t count = size_t(width) * size_t(height) * size_t(channels);
  std::vector<float> values(count);
  if (count == 0) return values;
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  if (texture.isInteger()) {
    std::vector<GLuint> raw(count);
    const GLenum format = channels == 4 ? GL_RGBA_INTEGER
                          : channels == 2 ? GL_RG_INTEGER
                                          : GL_RED_INTEGER;
    glGetTextureSubImage(texture.id(), 0, x0, y0, layer, width, height, 1, format,
                         GL_UNSIGNED_INT, GLsizei(raw.size() * sizeof(GLuint)), raw.data());
    std::transform(raw.begin(), raw.end(), values.begin(), [](GLuint v) { return float(v); });
    return values;
  }
  GLenum format = channels == 4 ? GL_RGBA : channels == 2 ? GL_RG : GL_RED;
  if (texture.internalFormat() == GL_DEPTH_COMPONENT32F) format = GL_DEPTH_COMPONENT;
  glGetTextureSubImage(texture.id(), 0, x0, y0, layer, width, height, 1, format, GL_FLOAT,
                       GLsizei(values.size() * sizeof(float)), values.data());
  return values;
}

std::array<float, 4> readTexel(const GlTexture& texture, int x, int y, int layer) {
  std::array<float, 4> texel{0, 0, 0, 0};
  if (x < 0 || y < 0 || x >= texture.width() || y >= texture.height()) return texel;
  const std::vector<float> values = readRegion(texture, x, y, 1, 1, layer);
  std::copy(values.begin(), values.end(), texel.begin());
  return texel;
}

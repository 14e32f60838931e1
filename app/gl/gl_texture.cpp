#include "gl/gl_texture.h"

#include "gl/gl_context.h"

#include <cstdio>
#include <algorithm>
#include <stdexcept>

namespace {
void drainGlErrors() {
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {
  }
}
}  // namespace

void clearGlErrors() {
  drainGlErrors();
  setGlErrorsHandled(true);  // until checkGlAllocation, which reports them
}

void checkGlAllocation(const std::string& what, size_t bytes) {
  setGlErrorsHandled(false);
  const GLenum error = glGetError();
  if (error == GL_NO_ERROR) return;
  drainGlErrors();
  char size[64];
  std::snprintf(size, sizeof size, "%.1f MiB", double(bytes) / (1024.0 * 1024.0));
  if (error == GL_OUT_OF_MEMORY)
    throw std::runtime_error("OpenGL is out of memory: cannot allocate " + what + " (" + size +
                             "); use a smaller image, map or scene");
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", error);
  throw std::runtime_error("OpenGL refused to allocate " + what + " (" + size + "): error " +
                           code + " (beyond the driver's limits?)");
}

namespace {
// Exact values: every read is a texelFetch, an imageLoad, a nearest sample or a gather.
// Clamped to the edge: the gathers of minmax_level.frag rely on it at the map's borders (a
// clamped texel repeats one already read).
void setNearestClamped(GLuint id) {
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}
}  // namespace

GlTexture::GlTexture(GLenum internalFormat, int width, int height, int layers, int levels)
    : format_(internalFormat), width_(width), height_(height), layers_(layers), levels_(levels) {
  clearGlErrors();
  glCreateTextures(layers > 0 ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D, 1, &id_);
  if (layers > 0)
    glTextureStorage3D(id_, levels, internalFormat, width, height, layers);
  else
    glTextureStorage2D(id_, levels, internalFormat, width, height);
  try {
    checkGlAllocation("a " + extentText() + " texture", bytes());
  } catch (...) {
    release();
    throw;
  }
  // NEAREST (not a mipmap filter): sampling reads the base level; a texelFetch names its
  // level (the min-max mipmap's readers, shaders/shared/minmax.glsl).
  setNearestClamped(id_);
}

GlTexture GlTexture::levelView(const GlTexture& source, int level) {
  if (source.isArray() || level < 0 || level >= source.levels())
    throw std::invalid_argument("GlTexture::levelView: level " + std::to_string(level) +
                                " of a 2D texture with " + std::to_string(source.levels()) +
                                " levels");
  GlTexture view;
  view.format_ = source.format_;
  view.width_ = source.levelWidth(level);
  view.height_ = source.levelHeight(level);
  // A view needs a name never bound, from glGenTextures (not glCreateTextures).
  glGenTextures(1, &view.id_);
  glTextureView(view.id_, GL_TEXTURE_2D, source.id_, source.format_, GLuint(level), 1, 0, 1);
  setNearestClamped(view.id_);
  return view;
}

void bindTextureForReading(GLuint unit, const GlTexture& texture) {
  glBindTextureUnit(unit, texture.id());
}

// Appends only: `"x" + std::to_string(...)` (a literal plus a temporary string) makes GCC 12
// print a false -Wrestrict from <string> (GCC bug 105329).
std::string GlTexture::extentText() const {
  std::string text = std::to_string(width_);
  text.append("x").append(std::to_string(height_));
  if (layers_ > 0) text.append("x").append(std::to_string(layers_));
  if (levels_ > 1) text.append(" (").append(std::to_string(levels_)).append(" mip levels)");
  return text;
}

GlTexture& GlTexture::operator=(GlTexture&& other) noexcept {
  if (this != &other) {
    release();
    std::swap(id_, other.id_);
    format_ = other.format_;
    width_ = other.width_;
    height_ = other.height_;
    layers_ = other.layers_;
    levels_ = other.levels_;
  }
  return *this;
}

void GlTexture::release() {
  if (id_) glDeleteTextures(1, &id_);
  id_ = 0;
}

int GlTexture::channelCount() const {
  switch (format_) {
    case GL_RGBA32F: case GL_RGBA8: case GL_RGBA32UI: case GL_RGBA16F: return 4;
    case GL_RG32F: case GL_RG32UI: return 2;
    default: return 1;
  }
}

size_t GlTexture::bytes() const {
  int texelBytes = 4 * channelCount();  // 32-bit channels
  if (format_ == GL_RGBA8 || format_ == GL_R8UI || format_ == GL_R8) texelBytes = channelCount();
  if (format_ == GL_RGBA16F) texelBytes = 8;
  size_t texels = 0;
  for (int level = 0; level < levels_; ++level)
    texels += size_t(levelWidth(level)) * size_t(levelHeight(level));
  return texels * size_t(std::max(layers_, 1)) * size_t(texelBytes);
}

bool GlTexture::isInteger() const {
  return format_ == GL_R32UI || format_ == GL_RG32UI || format_ == GL_RGBA32UI ||
         format_ == GL_R8UI;
}

std::vector<float> GlTexture::readFloats(int layer) const { return readImage(0, layer); }

std::vector<float> GlTexture::readLevelFloats(int level) const {
  if (isArray() || level < 0 || level >= levels_)
    throw std::invalid_argument("GlTexture::readLevelFloats: level " + std::to_string(level) +
                                " of a 2D texture with " + std::to_string(levels_) + " levels");
  return readImage(level, 0);
}

std::vector<float> GlTexture::readImage(int level, int layer) const {
  const int channels = channelCount();
  const int width = levelWidth(level), height = levelHeight(level);
  const size_t count = size_t(width) * height * channels;
  std::vector<float> values(count);
  GLenum format = channels == 4 ? GL_RGBA : channels == 2 ? GL_RG : GL_RED;
  if (format_ == GL_DEPTH_COMPONENT32F) format = GL_DEPTH_COMPONENT;
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  if (isInteger()) {
    std::vector<GLuint> raw(count);
    const GLenum integerFormat = channels == 4 ? GL_RGBA_INTEGER
                                 : channels == 2 ? GL_RG_INTEGER
                                                 : GL_RED_INTEGER;
    glGetTextureSubImage(id_, level, 0, 0, layer, width, height, 1, integerFormat,
                         GL_UNSIGNED_INT, GLsizei(raw.size() * sizeof(GLuint)), raw.data());
    for (size_t i = 0; i < count; ++i) values[i] = float(raw[i]);
    return values;
  }
  glGetTextureSubImage(id_, level, 0, 0, layer, width, height, 1, format, GL_FLOAT,
                       GLsizei(values.size() * sizeof(float)), values.data());
  return values;
}

void GlFramebuffer::checkComplete(const char* who) const {
  const GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error(std::string(who) + ": framebuffer incomplete (status 0x" +
                             std::to_string(status) + ")");
}

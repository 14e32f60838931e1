// Owning handles for the GL objects the stages create, and float read-back.
#pragma once
#include <epoxy/gl.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

// Every GL allocation is followed by this check: GL_OUT_OF_MEMORY (or a size the driver
// refuses) throws, naming what was allocated and its size, instead of leaving an object
// without storage that later renders, reads back or exports as garbage. Errors pending
// from earlier calls are cleared first by clearGlErrors(), and the errors between the two
// calls are the check's to report (not failures of the debug callback, gl_context.h).
void clearGlErrors();
void checkGlAllocation(const std::string& what, size_t bytes);

class GlTexture {
public:
  GlTexture() = default;
  // A 2D texture (layers == 0) or a 2D array texture (layers >= 1) with `levels` mip levels
  // (glTextureStorage: level m is max(1, floor(W / 2^m)) x max(1, floor(H / 2^m)); at most
  // floor(log2(max(W, H))) + 1 levels). Only the min-max mipmap has more than one.
  GlTexture(GLenum internalFormat, int width, int height, int layers = 0, int levels = 1);
  // A texture view (glTextureView, GL 4.5 §8.18) of mip level `level` of a 2D `source`: a
  // texture of its own with one level, whose level 0 is that level's storage (writes through
  // either are seen by both). What reads or draws one level alone uses it: the min-max
  // build (a level read while the next is drawn), the window's view of a level.
  static GlTexture levelView(const GlTexture& source, int level);
  ~GlTexture() { release(); }
  GlTexture(GlTexture&& other) noexcept { *this = std::move(other); }
  GlTexture& operator=(GlTexture&& other) noexcept;
  GlTexture(const GlTexture&) = delete;
  GlTexture& operator=(const GlTexture&) = delete;

  GLuint id() const { return id_; }
  GLenum internalFormat() const { return format_; }
  int width() const { return width_; }
  int height() const { return height_; }
  int layers() const { return layers_; }
  bool isArray() const { return layers_ > 0; }
  int levels() const { return levels_; }
  // Texels of mip level `level` per axis (0 for an empty texture).
  int levelWidth(int level) const { return width_ > 0 ? std::max(1, width_ >> level) : 0; }
  int levelHeight(int level) const { return height_ > 0 ? std::max(1, height_ >> level) : 0; }
  // "WxH", or "WxHxL" for an array texture (messages, the bench's memory table).
  std::string extentText() const;
  int channelCount() const;  // channels of the internal format (depth: 1)
  bool isInteger() const;    // R32UI and friends
  // Bytes of its mip levels over every layer, from the internal format and the sizes (what
  // the format needs; the driver may pad).
  size_t bytes() const;

  // Reads layer `layer` of mip level 0 as floats (integer formats converted), row 0 at the
  // bottom (GL order).
  std::vector<float> readFloats(int layer = 0) const;
  // Reads mip level `level` of a 2D texture, levelWidth(level) x levelHeight(level) texels.
  std::vector<float> readLevelFloats(int level) const;

private:
  void release();
  std::vector<float> readImage(int level, int layer) const;
  GLuint id_ = 0;
  GLenum format_ = 0;
  int width_ = 0, height_ = 0, layers_ = 0, levels_ = 1;
};

// Binds `texture` to texture unit `unit`, where a shader reads it with texelFetch (every
// texture is NEAREST and immutable, so it is complete and a fetch returns the texel of the
// level it names).
void bindTextureForReading(GLuint unit, const GlTexture& texture);

// Framebuffers and buffers are created on first use, so stages can be declared (for --set,
// help, tests of parameters) before a GL context exists.
class GlFramebuffer {
public:
  GlFramebuffer() = default;
  ~GlFramebuffer() { if (id_) glDeleteFramebuffers(1, &id_); }
  GlFramebuffer(const GlFramebuffer&) = delete;
  GlFramebuffer& operator=(const GlFramebuffer&) = delete;
  GLuint id() const {
    if (!id_) glCreateFramebuffers(1, &id_);
    return id_;
  }
  // Throws with the status name when the attachments are incomplete.
  void checkComplete(const char* who) const;

private:
  mutable GLuint id_ = 0;
};

class GlBuffer {
public:
  GlBuffer() = default;
  ~GlBuffer() { if (id_) glDeleteBuffers(1, &id_); }
  GlBuffer(const GlBuffer&) = delete;
  GlBuffer& operator=(const GlBuffer&) = delete;
  GLuint id() const {
    if (!id_) glCreateBuffers(1, &id_);
    return id_;
  }
  void upload(const void* data, size_t bytes) {
    clearGlErrors();
    glNamedBufferData(id(), GLsizeiptr(bytes), data, GL_DYNAMIC_DRAW);
    checkGlAllocation("a buffer", bytes);
  }

private:
  mutable GLuint id_ = 0;
};

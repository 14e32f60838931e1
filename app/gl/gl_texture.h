// Owning handles for the GL objects the stages create, and float read-back.
#pragma once
#include <epoxy/gl.h>

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
  // A 2D texture (layers == 0) or a 2D array texture (layers >= 1), one mip level.
  GlTexture(GLenum internalFormat, int width, int height, int layers = 0);
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
  // "WxH", or "WxHxL" for an array texture (messages, the bench's memory table).
  std::string extentText() const;
  int channelCount() const;  // channels of the internal format (depth: 1)
  bool isInteger() const;    // R32UI and friends
  // Bytes of its one mip level over every layer, from the internal format and the size
  // (what the format needs; the driver may pad).
  size_t bytes() const;

  // Reads layer `layer` as floats (integer formats converted), row 0 at the bottom (GL order).
  std::vector<float> readFloats(int layer = 0) const;

private:
  void release();
  GLuint id_ = 0;
  GLenum format_ = 0;
  int width_ = 0, height_ = 0, layers_ = 0;
};

// Binds `texture` to texture unit `unit`, where a shader reads it with texelFetch (every
// texture is NEAREST and has one level, so it is complete and a fetch returns the texel).
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

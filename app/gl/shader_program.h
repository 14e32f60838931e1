// GLSL programs loaded from shaders/ with our own `#include "file"` resolver, so the layout
// headers (shaders/shared/, and a stage's own beside its C++ in stages/<family>/<stage>/) are
// read by both C++ and GLSL. An include is looked up in the including file's folder, then the
// shader directory, then the source tree. A failed (re)load keeps the last good program and
// returns the compiler log.
#pragma once
#include <epoxy/gl.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

// $PENUMBRA_SHADER_DIR, else <source>/shaders. The override replaces the shader tree alone:
// headers included from the source tree (stages/...) are always this checkout's.
std::filesystem::path shaderDirectory();

// Reads `file` (relative to shaderDirectory()) with every #include expanded once, with
// #line directives so compiler messages name the right line; `files` receives the source
// string numbers' files (0: `file`). Throws std::runtime_error.
std::string loadShaderSource(const std::string& file, const std::string& defines = "",
                             std::vector<std::string>* files = nullptr);
// A compiler log with source string numbers replaced by file names:
// "0:200014(3): error ..." -> "shared/trace_ray.glsl:14:3: error ..." (file 2, line 14).
std::string nameSourcesInLog(const std::string& log, const std::vector<std::string>& files);

class ShaderProgram {
public:
  struct Source { GLenum type; std::string file; };
  ShaderProgram() = default;
  ShaderProgram(std::vector<Source> sources, std::string defines = "");
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  // Compiles and links; on failure keeps the previous program, returns false and the log.
  bool reload(std::string& log);
  // Built on first use (so stages can be declared before a GL context exists); throws
  // std::runtime_error with the compiler log if the first build fails.
  GLuint id();
  void use() { glUseProgram(id()); }
  const std::vector<Source>& sources() const { return sources_; }
  const std::string& defines() const { return defines_; }
  bool fromVariants() const { return fromVariants_; }  // one of a ShaderVariants' programs

  // Every live program, for hot reload.
  static bool reloadAll(std::string& log);

private:
  std::vector<Source> sources_;
  std::string defines_;
  GLuint program_ = 0;
  bool fromVariants_ = false;
  friend class ShaderVariants;
};

// The programs of the same sources compiled with different #defines (specializations),
// each built on first use and kept: operator[] with the defines' text. A variant first
// used after a broken edit on disk throws like any first build (id()); the variants built
// before keep their last good program on reload.
// `variants`: every defines text the owner can ask for, so that `penumbra shaders --dump`
// writes (and the tests validate) each program the application can build; operator[] with
// a text not among them throws std::logic_error. Empty: any text (not dumped).
class ShaderVariants {
public:
  explicit ShaderVariants(std::vector<ShaderProgram::Source> sources,
                          std::vector<std::string> variants = {});
  ~ShaderVariants();
  ShaderVariants(const ShaderVariants&) = delete;
  ShaderVariants& operator=(const ShaderVariants&) = delete;
  ShaderProgram& operator[](const std::string& defines);
  const std::vector<ShaderProgram::Source>& sources() const { return sources_; }
  const std::vector<std::string>& variants() const { return variants_; }

private:
  std::vector<ShaderProgram::Source> sources_;
  std::vector<std::string> variants_;
  std::map<std::string, std::unique_ptr<ShaderProgram>> programs_;
};

// Every concatenation of one text from each axis, in order: {{"a", "b"}, {"1", "2"}} gives
// "a1", "a2", "b1", "b2" (the define combinations of a ShaderVariants).
std::vector<std::string> defineCombinations(const std::vector<std::vector<std::string>>& axes);

// The programs the live ShaderPrograms and ShaderVariants can build (each ShaderVariants with
// its declared variants), once each: what `penumbra shaders --dump` writes.
struct ProgramVariant {
  std::vector<ShaderProgram::Source> sources;
  std::string defines;
};
std::vector<ProgramVariant> buildablePrograms();

// The memory barriers a compute pass issues after it, named by what reads its results next
// (a framebuffer write needs none: later commands see it):
//   kImageResults  images it stored, read by texelFetch, imageLoad, a copy or a read-back;
//   kBufferResults storage buffers it wrote, read by a shader, a copy or a read-back;
//   kCommandResults an indirect dispatch command it wrote.
constexpr GLbitfield kImageResults = GL_TEXTURE_FETCH_BARRIER_BIT |
                                     GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                                     GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT;
constexpr GLbitfield kBufferResults = GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT;
constexpr GLbitfield kCommandResults = GL_COMMAND_BARRIER_BIT;

// Dispatches a compute program over width x height in 8x8 groups, split into row bands of
// at most `rowsPerBand` rows (a long run can then be interleaved with the window's frames),
// then the barriers `barriers`. The band's first row is passed in the uniform `uRowOffset`
// (location 0).
void dispatchRows(int width, int height, GLbitfield barriers, int rowsPerBand = 1 << 30);


// GLSL programs loaded from shaders/ with our own `#include "file"` resolver, so the layout
// headers in shaders/shared/ are read by both C++ and GLSL. A failed (re)load keeps the last
// good program and returns the compiler log.
#pragma once
#include <epoxy/gl.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

std::filesystem::path shaderDirectory();  // $PENUMBRA_SHADER_DIR, else <source>/shaders

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

  // Every live program, for hot reload.
  static bool reloadAll(std::string& log);

private:
  std::vector<Source> sources_;
  std::string defines_;
  GLuint program_ = 0;
};

// The programs of the same sources compiled with different #defines (specializations),
// each built on first use and kept: operator[] with the defines' text. A variant first
// used after a broken edit on disk throws like any first build (id()); the variants built
// before keep their last good program on reload.
class ShaderVariants {
public:
  explicit ShaderVariants(std::vector<ShaderProgram::Source> sources) : sources_(std::move(sources)) {}
  ShaderProgram& operator[](const std::string& defines);

private:
  std::vector<ShaderProgram::Source> sources_;
  std::map<std::string, std::unique_ptr<ShaderProgram>> programs_;
};

// Dispatches a compute program over width x height in 8x8 groups, split into row bands of
// at most `rowsPerBand` rows (llvmpipe blocks the calling thread for the whole dispatch).
// The band's first row is passed in the uniform `uRowOffset` (location 0).
void dispatchRows(int width, int height, int rowsPerBand = 1 << 30);

// Dispatches a per-tile compute program (shaders/shared/tile_pass.glsl): one invocation per
// tile x tile pixels of width x height.
void dispatchTiles(int width, int height, int tile);

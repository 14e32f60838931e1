#include "gl/shader_program.h"

#include <algorithm>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

namespace {

std::vector<ShaderProgram*>& livePrograms() {
  static std::vector<ShaderProgram*> programs;
  return programs;
}

void expandIncludes(const std::filesystem::path& path, int fileIndex, std::set<std::string>& seen,
                    std::ostringstream& out, std::vector<std::string>& files) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("shader file not found: " + path.string());
  static const std::regex includeLine(R"re(^\s*#\s*include\s+"([^"]+)"\s*$)re");
  std::string line;
  int lineNumber = 0;
  out << "#line 1 " << fileIndex << "\n";
  while (std::getline(in, line)) {
    ++lineNumber;
    std::smatch match;
    if (!std::regex_match(line, match, includeLine)) {
      out << line << "\n";
      continue;
    }
    const auto included = (path.parent_path() / match[1].str()).lexically_normal();
    if (seen.insert(included.string()).second) {
      files.push_back(included.string());
      expandIncludes(included, int(files.size()) - 1, seen, out, files);
    }
    out << "#line " << lineNumber + 1 << " " << fileIndex << "\n";
  }
}

GLuint compile(GLenum type, const std::string& file, const std::string& defines,
               std::string& log) {
  std::string source;
  try {
    source = loadShaderSource(file, defines);
  } catch (const std::exception& error) {
    log += error.what();
    log += "\n";
    return 0;
  }
  GLuint shader = glCreateShader(type);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string message(std::max(length, 1), '\0');
    glGetShaderInfoLog(shader, length, nullptr, message.data());
    log += file + ": " + message.c_str() + "\n";
    glDeleteShader(shader);
    return 0;
  }
  return shader;
}

}  // namespace

std::filesystem::path shaderDirectory() {
  if (const char* override = std::getenv("PENUMBRA_SHADER_DIR")) return override;
  return std::filesystem::path(PENUMBRA_SOURCE_DIR) / "shaders";
}

std::string loadShaderSource(const std::string& file, const std::string& defines) {
  std::ostringstream out;
  out << "#version 450 core\n" << defines << "\n";
  std::set<std::string> seen;
  std::vector<std::string> files{file};
  expandIncludes(shaderDirectory() / file, 0, seen, out, files);
  return out.str();
}

ShaderProgram::ShaderProgram(std::vector<Source> sources, std::string defines)
    : sources_(std::move(sources)), defines_(std::move(defines)) {
  livePrograms().push_back(this);
}

GLuint ShaderProgram::id() {
  std::string log;
  if (!program_ && !reload(log)) throw std::runtime_error("shader build failed:\n" + log);
  return program_;
}

ShaderProgram::~ShaderProgram() {
  auto& programs = livePrograms();
  programs.erase(std::remove(programs.begin(), programs.end(), this), programs.end());
  if (program_) glDeleteProgram(program_);
}

bool ShaderProgram::reload(std::string& log) {
  std::vector<GLuint> shaders;
  bool ok = true;
  for (const Source& source : sources_) {
    GLuint shader = compile(source.type, source.file, defines_, log);
    ok = ok && shader != 0;
    if (shader) shaders.push_back(shader);
  }
  GLuint program = 0;
  if (ok) {
    program = glCreateProgram();
    for (GLuint shader : shaders) glAttachShader(program, shader);
    glLinkProgram(program);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) {
      GLint length = 0;
      glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
      std::string message(std::max(length, 1), '\0');
      glGetProgramInfoLog(program, length, nullptr, message.data());
      log += "link " + sources_.front().file + ": " + message.c_str() + "\n";
      glDeleteProgram(program);
      program = 0;
      ok = false;
    }
  }
  for (GLuint shader : shaders) glDeleteShader(shader);
  if (!ok) return false;
  if (program_) glDeleteProgram(program_);
  program_ = program;
  return true;
}

bool ShaderProgram::reloadAll(std::string& log) {
  bool ok = true;
  for (ShaderProgram* program : livePrograms())
    if (program->program_) ok = program->reload(log) && ok;
  return ok;
}

void dispatchRows(int width, int height, int rowsPerBand) {
  rowsPerBand = std::max(8, rowsPerBand / 8 * 8);
  for (int row = 0; row < height; row += rowsPerBand) {
    const int rows = std::min(rowsPerBand, height - row);
    glUniform1i(0, row);
    glDispatchCompute((width + 7) / 8, (rows + 7) / 8, 1);
  }
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
}

#include "io/shader_dump.h"

#include <cstdio>
#include <fstream>
#include <system_error>

#include "base/input_error.h"
#include "core/pipeline.h"
#include "gl/shader_program.h"

namespace {

const char* extensionOf(GLenum type) {
  switch (type) {
    case GL_VERTEX_SHADER: return ".vert";
    case GL_FRAGMENT_SHADER: return ".frag";
    case GL_COMPUTE_SHADER: return ".comp";
    case GL_GEOMETRY_SHADER: return ".geom";
    default: return ".glsl";
  }
}

void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out.flush()) throw InputError("cannot write '" + path.string() + "'");
}

std::string oneLine(std::string text) {
  while (!text.empty() && text.back() == '\n') text.pop_back();
  for (char& c : text)
    if (c == '\n') c = ';';
  return text;
}

}  // namespace

int dumpShaderSources(const std::filesystem::path& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error || !std::filesystem::is_directory(directory))
    throw InputError("cannot create the directory '" + directory.string() + "'");
  // Every stage's programs exist once the pipeline is declared (no GL context is needed:
  // programs are built on first use).
  Pipeline pipeline;
  const std::vector<ProgramVariant> programs = buildablePrograms();
  std::string listing;
  for (size_t i = 0; i < programs.size(); ++i) {
    char number[32];
    std::snprintf(number, sizeof number, "%04zu", i);
    listing += number;
    for (const ShaderProgram::Source& source : programs[i].sources) {
      const std::string stem = std::filesystem::path(source.file).stem().string();
      const std::string name = std::string(number) + "-" + stem + extensionOf(source.type);
      writeFile(directory / name, loadShaderSource(source.file, programs[i].defines));
      listing += " " + name;
    }
    listing += " | " + oneLine(programs[i].defines) + "\n";
  }
  writeFile(directory / "programs.txt", listing);
  return int(programs.size());
}

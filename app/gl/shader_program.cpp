#include "gl/shader_program.h"

#include "shared/screen_pass_layout.h"

#include <algorithm>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

namespace {

// Each file's lines are numbered from fileIndex * kLinesPerFile (and the #line source number
// is the file index too): Mesa reports source string 0 whatever #line says, so the line
// number alone must tell the file.
constexpr long kLinesPerFile = 100000;

std::vector<ShaderProgram*>& livePrograms() {
  static std::vector<ShaderProgram*> programs;
  return programs;
}
std::vector<ShaderVariants*>& liveVariants() {
  static std::vector<ShaderVariants*> variants;
  return variants;
}

std::filesystem::path sourceDirectory() { return PENUMBRA_SOURCE_DIR; }

// `#include "name"` from the file `from`: the including file's folder, then the shader
// directory (shaders/, or $PENUMBRA_SHADER_DIR), then the source tree, where a stage's layout
// header sits beside its C++ ("stages/monte_carlo/classify/classify_layout.h"; docs/design.md
// "Where a stage's files are"). The source tree is not replaced by $PENUMBRA_SHADER_DIR: the
// layout headers are compiled into the C++ too. A name found nowhere stays relative to `from`
// (the "not found" message names it there).
std::filesystem::path resolveInclude(const std::filesystem::path& from, const std::string& name) {
  const std::filesystem::path local = (from.parent_path() / name).lexically_normal();
  for (const std::filesystem::path& candidate :
       {local, (shaderDirectory() / name).lexically_normal(),
        (sourceDirectory() / name).lexically_normal()})
    if (std::filesystem::is_regular_file(candidate)) return candidate;
  return local;
}

void expandIncludes(const std::filesystem::path& path, int fileIndex, std::set<std::string>& seen,
                    std::ostringstream& out, std::vector<std::string>& files) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("shader file not found: " + path.string());
  static const std::regex includeLine(R"re(^\s*#\s*include\s+"([^"]+)"\s*$)re");
  std::string line;
  int lineNumber = 0;
  out << "#line " << fileIndex * kLinesPerFile + 1 << " " << fileIndex << "\n";
  while (std::getline(in, line)) {
    ++lineNumber;
    std::smatch match;
    if (!std::regex_match(line, match, includeLine)) {
      out << line << "\n";
      continue;
    }
    const auto included = resolveInclude(path, match[1].str());
    if (seen.insert(included.string()).second) {
      files.push_back(included.string());
      expandIncludes(included, int(files.size()) - 1, seen, out, files);
    }
    out << "#line " << fileIndex * kLinesPerFile + lineNumber + 1 << " " << fileIndex << "\n";
  }
}

GLuint compile(GLenum type, const std::string& file, const std::string& defines,
               std::string& log) {
  std::string source;
  std::vector<std::string> files;
  try {
    source = loadShaderSource(file, defines, &files);
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
    log += file + ":\n" + nameSourcesInLog(message.c_str(), files) + "\n";
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

std::string loadShaderSource(const std::string& file, const std::string& defines,
                             std::vector<std::string>* files) {
  std::ostringstream out;
  out << "#version 450 core\n" << defines << "\n";
  std::set<std::string> seen;
  std::vector<std::string> names{file};
  expandIncludes(shaderDirectory() / file, 0, seen, out, names);
  if (files) {
    // Names relative to the shader directory, as a reader finds them in shaders/ (a layout
    // header from the source tree: relative to it, "stages/...").
    for (size_t i = 1; i < names.size(); ++i)
      for (const std::filesystem::path& root : {shaderDirectory(), sourceDirectory()}) {
        const std::string relative =
            std::filesystem::path(names[i]).lexically_relative(root).string();
        if (!relative.empty() && relative.rfind("..", 0) != 0) {
          names[i] = relative;
          break;
        }
      }
    *files = std::move(names);
  }
  return out.str();
}

std::string nameSourcesInLog(const std::string& log, const std::vector<std::string>& files) {
  // "0:200014(3): error" (Mesa) and "2(200014) : error" (NVIDIA): line 200014 is line 14 of
  // files[2] (see kLinesPerFile).
  static const std::regex mesa(R"re((^|\n)(\d+):(\d+)\((\d+)\))re");
  static const std::regex nvidia(R"re((^|\n)(\d+)\((\d+)\))re");
  auto rename = [&](const std::string& text, const std::regex& pattern, bool withColumn) {
    std::string result;
    size_t last = 0;
    for (auto match = std::sregex_iterator(text.begin(), text.end(), pattern);
         match != std::sregex_iterator(); ++match) {
      const long encoded = std::stol((*match)[3].str());
      const size_t index = size_t(encoded / kLinesPerFile);
      const std::string place =
          index < files.size()
              ? files[index] + ":" + std::to_string(encoded % kLinesPerFile)
              : (*match)[2].str() + ":" + (*match)[3].str();
      // Appends only: `":" + (*match)[4].str()` makes GCC 12 print a false -Wrestrict.
      result.append(text, last, size_t(match->position()) - last).append((*match)[1].str());
      result.append(place);
      if (withColumn) result.append(":").append((*match)[4].str());
      last = size_t(match->position() + match->length());
    }
    return result + text.substr(last);
  };
  return rename(rename(log, mesa, true), nvidia, false);
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

namespace {

// A program deleted while current stays current until unbound, and its name stays in
// GL_CURRENT_PROGRAM: whoever saves and restores the current program (ImGui's renderer does)
// then binds a name that no longer exists, GL_INVALID_VALUE in glUseProgram. Unbind first.
void deleteProgram(GLuint program) {
  GLint current = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &current);
  if (GLuint(current) == program) glUseProgram(0);
  glDeleteProgram(program);
}

}  // namespace

ShaderProgram::~ShaderProgram() {
  auto& programs = livePrograms();
  programs.erase(std::remove(programs.begin(), programs.end(), this), programs.end());
  if (program_) deleteProgram(program_);
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
  if (program_) deleteProgram(program_);
  program_ = program;
  return true;
}

bool ShaderProgram::reloadAll(std::string& log) {
  bool ok = true;
  for (ShaderProgram* program : livePrograms())
    if (program->program_) ok = program->reload(log) && ok;
  return ok;
}

ShaderVariants::ShaderVariants(std::vector<ShaderProgram::Source> sources,
                               std::vector<std::string> variants)
    : sources_(std::move(sources)), variants_(std::move(variants)) {
  liveVariants().push_back(this);
}

ShaderVariants::~ShaderVariants() {
  auto& all = liveVariants();
  all.erase(std::remove(all.begin(), all.end(), this), all.end());
}

ShaderProgram& ShaderVariants::operator[](const std::string& defines) {
  if (!variants_.empty() && std::find(variants_.begin(), variants_.end(), defines) == variants_.end())
    throw std::logic_error("shader variant not declared for " + sources_.back().file + ": " +
                           defines);
  std::unique_ptr<ShaderProgram>& program = programs_[defines];
  if (!program) {
    program = std::make_unique<ShaderProgram>(sources_, defines);
    program->fromVariants_ = true;
  }
  return *program;
}

void dispatchRows(int width, int height, GLbitfield barriers, int rowsPerBand) {
  rowsPerBand = std::max(8, rowsPerBand / 8 * 8);
  for (int row = 0; row < height; row += rowsPerBand) {
    const int rows = std::min(rowsPerBand, height - row);
    glUniform1i(ROW_OFFSET_LOCATION, row);
    glDispatchCompute((width + 7) / 8, (rows + 7) / 8, 1);
  }
  glMemoryBarrier(barriers);
}

std::vector<std::string> defineCombinations(const std::vector<std::vector<std::string>>& axes) {
  std::vector<std::string> result{""};
  for (const std::vector<std::string>& axis : axes) {
    std::vector<std::string> next;
    for (const std::string& prefix : result)
      for (const std::string& choice : axis) next.push_back(prefix + choice);
    result = std::move(next);
  }
  return result;
}

std::vector<ProgramVariant> buildablePrograms() {
  std::vector<ProgramVariant> result;
  std::set<std::string> seen;
  auto add = [&](const std::vector<ShaderProgram::Source>& sources, const std::string& defines) {
    std::string key = defines;
    for (const ShaderProgram::Source& source : sources) key += "|" + source.file;
    if (seen.insert(key).second) result.push_back({sources, defines});
  };
  for (const ShaderProgram* program : livePrograms())
    if (!program->fromVariants()) add(program->sources(), program->defines());
  for (const ShaderVariants* variants : liveVariants())
    for (const std::string& defines : variants->variants()) add(variants->sources(), defines);
  return result;
}

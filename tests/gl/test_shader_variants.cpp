// Every program variant the pipeline can build (`penumbra shaders --dump`) compiles with a
// second, independent GLSL front end: Khronos' glslangValidator (Debian glslang-tools),
// not only with the driver the tests run on.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "gl/shader_program.h"
#include "support/command.h"
#include "support/temp_directory.h"

namespace {

struct Output {
  int status;
  std::string text;
};
Output run(const std::string& command) {
  Output result{-1, ""};
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  while (size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) result.text.append(buffer, n);
  result.status = pclose(pipe);
  return result;
}

bool haveGlslang() { return run("command -v glslangValidator").status == 0; }

}  // namespace

TEST(ShaderVariants, CombinationsAreTheCrossProduct) {
  EXPECT_EQ(defineCombinations({{"a", "b"}, {"1", "2", "3"}}),
            (std::vector<std::string>{"a1", "a2", "a3", "b1", "b2", "b3"}));
  EXPECT_EQ(defineCombinations({}), std::vector<std::string>{""});
}

TEST(ShaderVariants, AnUndeclaredVariantIsRefused) {
  // No GL context is needed: operator[] only creates the program object; it is built on
  // first use.
  ShaderVariants variants({{GL_COMPUTE_SHADER, "monte_carlo/trace/trace.comp"}}, {"#define A 1\n"});
  EXPECT_NO_THROW(variants["#define A 1\n"]);
  EXPECT_THROW(variants["#define A 2\n"], std::logic_error);
}

TEST(ShaderVariants, EveryDumpedVariantPassesGlslangValidator) {
  if (!haveGlslang()) GTEST_SKIP() << "glslangValidator not installed (scripts/setup.sh)";
  const TempDirectory scratch("penumbra_shader_dump");
  const std::filesystem::path dir = scratch.path() / "dump";
  const CommandResult dump = runPenumbra("shaders --dump " + dir.string());
  ASSERT_EQ(dump.exitCode, 0) << dump.output;

  // programs.txt: "NNNN file file | defines" per program; every file exists.
  std::ifstream listing(dir / "programs.txt");
  std::string line;
  std::vector<std::vector<std::string>> programs;
  std::map<std::string, int> perSource;  // programs per last source file
  while (std::getline(listing, line)) {
    std::istringstream words(line.substr(0, line.find(" | ")));
    std::string number, file;
    words >> number;
    std::vector<std::string> files;
    while (words >> file) {
      EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
      files.push_back(file);
    }
    ASSERT_FALSE(files.empty()) << line;
    ++perSource[files.back().substr(5)];
    programs.push_back(files);
  }
  // The trace's specializations, deferred and forward: 2 hierarchies x 3 searches x 3 layer
  // counts x records on/off x cost on/off x 8 hashes.
  EXPECT_EQ(perSource["trace.comp"], 2 * 3 * 3 * 2 * 2 * 8);
  EXPECT_EQ(perSource["trace_forward.frag"], 2 * 3 * 3 * 2 * 2 * 8);
  EXPECT_EQ(perSource["classify.frag"], 2);
  EXPECT_EQ(perSource["filter.comp"], 1);
  EXPECT_EQ(perSource["raster4d_occlusion.comp"], 64 - 8 + 1);

  // Each file compiled on its own, many to one glslangValidator run.
  std::vector<std::string> files;
  for (const auto& program : programs) files.insert(files.end(), program.begin(), program.end());
  int failures = 0;
  for (size_t first = 0; first < files.size(); first += 200) {
    std::string command = "cd " + dir.string() + " && glslangValidator";
    for (size_t i = first; i < std::min(files.size(), first + 200); ++i) command += " " + files[i];
    const Output checked = run(command);
    if (checked.status != 0 || checked.text.find("ERROR") != std::string::npos) {
      ++failures;
      ADD_FAILURE() << checked.text.substr(0, 4000);
    }
  }
  EXPECT_EQ(failures, 0);
  // Programs of more than one stage also linked (interfaces between the stages), one per
  // distinct set of sources.
  std::set<std::string> linked;
  for (const auto& program : programs) {
    if (program.size() < 2) continue;
    std::string key;
    for (const std::string& file : program) key += file.substr(5) + " ";
    if (!linked.insert(key).second) continue;
    std::string command = "cd " + dir.string() + " && glslangValidator -l";
    for (const std::string& file : program) command += " " + file;
    const Output checked = run(command);
    EXPECT_TRUE(checked.status == 0 && checked.text.find("ERROR") == std::string::npos)
        << key << ":\n" << checked.text.substr(0, 4000);
  }
  EXPECT_GE(linked.size(), 5u);
}

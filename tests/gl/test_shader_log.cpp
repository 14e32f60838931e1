// Shader compiler messages name files, not #include numbers (app/gl/shader_program.h).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "gl/shader_program.h"
#include "support/gl_test.h"
#include "support/temp_directory.h"

TEST(ShaderLog, SourceNumbersBecomeFileNames) {
  const std::vector<std::string> files{"monte_carlo/trace/trace.comp", "shared/frame.glsl", "shared/trace_ray.glsl"};
  // Line numbers carry the file: file index x 100000 + line (shader_program.cpp).
  EXPECT_EQ(nameSourcesInLog("0:200014(3): error: `x' undeclared\n0:5(1): warning", files),
            "shared/trace_ray.glsl:14:3: error: `x' undeclared\nmonte_carlo/trace/trace.comp:5:1: warning");
  EXPECT_EQ(nameSourcesInLog("1(100007) : error C0000: syntax", files),
            "shared/frame.glsl:7 : error C0000: syntax");
  EXPECT_EQ(nameSourcesInLog("0:900001(1): error", files), "0:900001:1: error");  // unknown
}

TEST(ShaderLog, AnErrorInAnIncludedFileIsReportedThere) {
  headlessContext();
  const TempDirectory scratch("penumbra_shader_log");
  const std::filesystem::path& dir = scratch.path();
  std::filesystem::create_directories(dir / "shared");
  std::ofstream(dir / "broken.comp") << "#include \"shared/helper.glsl\"\n"
                                        "layout(local_size_x = 1) in;\nvoid main() { helper(); }\n";
  std::ofstream(dir / "shared/helper.glsl") << "void helper() {\n  float x = undefinedName;\n}\n";
  setenv("PENUMBRA_SHADER_DIR", dir.c_str(), 1);
  ShaderProgram program({{GL_COMPUTE_SHADER, "broken.comp"}});
  std::string log;
  EXPECT_FALSE(program.reload(log));
  unsetenv("PENUMBRA_SHADER_DIR");
  EXPECT_NE(log.find("shared/helper.glsl:2:"), std::string::npos) << log;
}

// A program deleted while current must not leave its name in GL_CURRENT_PROGRAM: ImGui's
// renderer saves and restores the current program, and restoring a deleted one was
// GL_INVALID_VALUE in glUseProgram (printed while the speed chart's live bench released its
// pipeline). Any GL error here fails the test, through a debug callback.
#include <gtest/gtest.h>

#include <memory>

#include "gl/shader_program.h"
#include "support/gl_test.h"

namespace {
int glErrors = 0;
}

TEST(ShaderProgramDelete, CurrentProgramIsUnboundBeforeItIsDeleted) {
  headlessContext();
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(
      [](GLenum, GLenum type, GLuint, GLenum, GLsizei, const GLchar* message, const void*) {
        if (type == GL_DEBUG_TYPE_ERROR) {
          ++glErrors;
          ADD_FAILURE() << "GL error: " << message;
        }
      },
      nullptr);
  ShaderProgram imgui({{GL_COMPUTE_SHADER, "shared/depth_bounds.comp"}});  // stands for ImGui's own
  for (bool reload : {false, true}) {
    auto program = std::make_unique<ShaderProgram>(
        std::vector<ShaderProgram::Source>{{GL_COMPUTE_SHADER, "shared/depth_bounds.comp"}});
    program->use();
    if (reload) {
      std::string log;
      ASSERT_TRUE(program->reload(log)) << log;  // replaces (deletes) the current program
    } else {
      program.reset();
    }
    GLint current = -1;
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    if (!reload) {
      EXPECT_EQ(current, 0);
    }
    imgui.use();                    // ImGui's renderer: its own program for the draw lists,
    glUseProgram(GLuint(current));  // then the saved one back
  }
  glUseProgram(0);
  glDebugMessageCallback(nullptr, nullptr);
  EXPECT_EQ(glErrors, 0);
}

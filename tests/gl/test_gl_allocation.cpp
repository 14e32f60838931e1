// Every GL allocation is checked (docs/reliability.md). A texture or buffer the driver cannot
// allocate (GL_OUT_OF_MEMORY, or a size past its limits) throws a message naming it and its size,
// and a pipeline run that needs one fails instead of rendering into nothing.
#include <gtest/gtest.h>

#include <string>

#include "gl/gl_texture.h"
#include "scene/scene_builtin.h"
#include "support/gl_test.h"

namespace {

std::string messageOf(const std::function<void()>& allocate) {
  try {
    allocate();
  } catch (const std::exception& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST(GlAllocation, ImpossibleTexturesAndBuffersThrowAndNameTheSize) {
  headlessContext();
  // 16384^2 x 2048 RGBA32F = 8 TiB: inside GL's per-dimension limits, beyond any memory.
  const std::string texture = messageOf([] { GlTexture t(GL_RGBA32F, 16384, 16384, 2048); });
  EXPECT_NE(texture.find("16384x16384x2048 texture"), std::string::npos) << texture;
  EXPECT_NE(texture.find("OpenGL"), std::string::npos) << texture;
  // Past the maximum size: refused by the driver, reported too.
  const std::string wide = messageOf([] { GlTexture t(GL_R32F, 1 << 20, 4); });
  EXPECT_NE(wide.find("1048576x4 texture"), std::string::npos) << wide;
  const std::string buffer = messageOf([] {
    GlBuffer b;
    b.upload(nullptr, size_t(1) << 42);  // 4 TiB
  });
  EXPECT_NE(buffer.find("out of memory"), std::string::npos) << buffer;
  EXPECT_NE(buffer.find("4194304.0 MiB"), std::string::npos) << buffer;
  // The context still works afterwards: no error left pending.
  GlTexture small(GL_R32F, 4, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(GlAllocation, APipelineRunPastTheLimitsFailsInsteadOfRenderingNothing) {
  headlessContext();
  std::vector<std::string> warnings;
  const Scene scene = loadScene("cube", warnings);
  GpuScene gpuScene(scene);
  Pipeline pipeline;
  Frame frame(scene, gpuScene, pipeline);
  frame.eyeWidth = 1 << 20;  // past GL_MAX_TEXTURE_SIZE
  frame.eyeHeight = 8;
  EXPECT_THROW(pipeline.run(frame), std::runtime_error);
}

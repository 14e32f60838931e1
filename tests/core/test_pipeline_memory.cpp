// Where time and memory go (docs/decisions/021-stage-timings.md): MiB per stage output from the
// declared formats and sizes, and the two ways of timing stages (glFinish on llvmpipe,
// GL_TIME_ELAPSED on a GPU; the query path is forced here to exercise it).
#include <gtest/gtest.h>

#include <cmath>

#include "shared_inputs/minmax/minmax_build.h"
#include "gl/nbuffer_build.h"
#include "scene/scene_builtin.h"
#include "support/gl_test.h"

TEST(PipelineMemory, MegabytesFollowTheFormatsAndSizes) {
  PipelineRun run(makeBuiltinScene("cube"), {"light.resolution=256"}, 64, 48);
  const double mib = 1024.0 * 1024.0;
  // RGBA32F: 16 bytes a texel; the N-buffer keeps nbufferLevelCount(256, 256) = 9 levels.
  EXPECT_EQ(run.frame->megabytes("nbuffer.levels"), 256.0 * 256 * 9 * 16 / mib);
  // The min-max mipmap: mip levels 128^2, 64^2, ..., 1 (levels 1 .. 8 of the hierarchy).
  double minmaxTexels = 0;
  for (int side = 128; side >= 1; side /= 2) minmaxTexels += double(side) * side;
  EXPECT_EQ(run.frame->megabytes("minmax.levels"), minmaxTexels * 16 / mib);
  EXPECT_EQ(run.frame->megabytes("trace.visibility"), 64.0 * 48 * 4 / mib);      // R32F
  EXPECT_EQ(run.frame->megabytes("light_layers.near"), 256.0 * 256 * 4 / mib);   // DEPTH32F
  EXPECT_EQ(run.frame->megabytes("gbuffer.albedo"), 64.0 * 48 * 4 / mib);        // RGBA8
  EXPECT_GT(run.frame->megabytes("classify.tracedPixels"), 0.0);                 // a buffer
  EXPECT_EQ(run.frame->megabytes("no_stage.nothing"), 0.0);
  EXPECT_EQ(run.frame->megabytes(run.pipeline->stage("nbuffer")),
            run.frame->megabytes("nbuffer.levels"));
  // The min-max mipmap in at most 1/8 of the N-buffer's memory at 2048^2
  // (docs/decisions/024-minmax-mipmap-levels.md): its mip levels from 1024^2 down.
  const glm::ivec2 big = minmaxBaseSize(2048, 2048);
  EXPECT_EQ(big, glm::ivec2(1024, 1024));
  EXPECT_EQ(minmaxMipLevels(2048, 2048), 11);
  double bigTexels = 0;
  for (int side = big.x; side >= 1; side /= 2) bigTexels += double(side) * side;
  EXPECT_LE(bigTexels, 2048.0 * 2048 * nbufferLevelCount(2048, 2048) / 8);
}

TEST(PipelineTiming, LlvmpipeUsesGlFinishAndQueriesWorkWhenForced) {
  PipelineRun run(makeBuiltinScene("cube"), {"light.resolution=128"}, 64, 64);
  EXPECT_EQ(run.pipeline->timingMethod(), "glFinish + steady clock");  // llvmpipe
  run.pipeline->setTiming(Pipeline::Timing::Queries);
  EXPECT_EQ(run.pipeline->timingMethod(), "GL_TIME_ELAPSED");
  run.pipeline->run(*run.frame, {"trace.visibility"});
  int ran = 0;
  for (const StageTime& time : run.pipeline->lastTimes()) {
    EXPECT_TRUE(std::isfinite(time.milliseconds) && time.milliseconds >= 0) << time.stage;
    ran += time.ran;
  }
  EXPECT_TRUE(run.pipeline->lastTime("trace").ran);
  EXPECT_FALSE(run.pipeline->lastTime("composite").ran);
  EXPECT_GE(ran, 5);
}

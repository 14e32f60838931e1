// Where the trace panel's "Show on ..." button draws a ray's visited windows
// (window/ui_graph.h rayOverlayTarget): over the N-buffer's levels, one map-sized layer each;
// over the near layer when the trace searched the min-max mipmap, whose smaller mip
// levels the windows (in level-0 texels) do not fit. trace.hierarchy=auto chooses the min-max
// mipmap on large maps (docs/decisions/024-minmax-mipmap-levels.md), so this is the default on the
// window's engine and dragon.
#include <gtest/gtest.h>

#include "scene/scene_builtin.h"
#include "support/gl_test.h"
#include "window/ui_graph.h"

TEST(WindowRayOverlay, TheNBufferShowsItsLevelsTheMinMaxMipmapItsLevelZero) {
  PipelineRun run(makeBuiltinScene("cube"), {"light.resolution=256", "trace.hierarchy=nbuffer"},
                  64, 48);
  EXPECT_TRUE(rayOverlayTarget(*run.pipeline, nullptr).output.size() > 0);  // before a run
  run.run();
  RayOverlayTarget target = rayOverlayTarget(*run.pipeline, run.frame.get());
  EXPECT_EQ(target.output, "nbuffer.levels");
  EXPECT_TRUE(target.perLevel);
  // 256^2 x 9 levels over 64 x 48 pixels: auto takes the min-max mipmap.
  ASSERT_EQ(run.pipeline->set("trace.hierarchy=auto"), "");
  run.run();
  ASSERT_EQ(run.pipeline->param("trace.hierarchy").asEnum(), "minmax");
  target = rayOverlayTarget(*run.pipeline, run.frame.get());
  EXPECT_EQ(target.output, "light_layers.near");
  EXPECT_FALSE(target.perLevel);
  // The windows are drawn in the map's texels: the near layer is that size, the mip levels are not.
  EXPECT_EQ(run.frame->texture(target.output).width(), 256);
  EXPECT_NE(run.frame->texture("minmax.levels").width(), 256);
}

// The idle window is cheap: once the run and the layout have settled, UI frames in which
// nothing changes are built (input, timers) but not drawn or swapped (app/window/
// ui_frame_change.h); a change (the red channel alone) is drawn.
#include <gtest/gtest.h>

#include <regex>

#include "support/window_test.h"

namespace {

// "frames LABEL: B built, D drawn"
bool frames(const std::string& output, const std::string& label, int& built, int& drawn) {
  std::smatch match;
  if (!std::regex_search(output, match, std::regex("frames " + label + ": ([0-9]+) built, ([0-9]+) drawn")))
    return false;
  built = std::stoi(match[1]);
  drawn = std::stoi(match[2]);
  return true;
}

}  // namespace

TEST(WindowIdle, FramesThatShowNothingNewAreNotDrawn) {
  REQUIRE_DISPLAY();
  const TempDirectory dir("penumbra_window_idle");
  // Settled first (the grid's first runs, under a loaded CI machine, take seconds), then 30
  // frames with nothing new.
  const auto script = writeScript(dir.path(), R"([
    {"layout": "grid"}, {"wait": 60}, {"print_frames": "a"}, {"wait": 30}, {"print_frames": "b"},
    {"channels": "R"}, {"wait": 3}, {"print_frames": "c"}])");
  const CommandResult run = runPenumbra("--width 640 --height 480 --script " + script.string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  int builtA = 0, drawnA = 0, builtB = 0, drawnB = 0, builtC = 0, drawnC = 0;
  ASSERT_TRUE(frames(run.output, "a", builtA, drawnA)) << run.output;
  ASSERT_TRUE(frames(run.output, "b", builtB, drawnB)) << run.output;
  ASSERT_TRUE(frames(run.output, "c", builtC, drawnC)) << run.output;
  EXPECT_GE(builtB - builtA, 30) << run.output;
  EXPECT_EQ(drawnB - drawnA, 0) << "nothing changed, yet frames were drawn:\n" << run.output;
  EXPECT_GE(drawnC - drawnB, 1) << "the red channel alone was not drawn:\n" << run.output;
}

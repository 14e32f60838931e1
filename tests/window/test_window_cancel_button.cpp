// A run in progress is stopped by a real mouse click on the window's Cancel button
// (tests/window/real_input_cancel.sh, xdotool on a private Xvfb): a soft-shadow-map run of
// many minutes shows the "running" overlay after a second, the click cancels it at its next
// SSM tile, the window stays open with its settings, and Ctrl+Q closes it with status 0.
#include <gtest/gtest.h>

#include <cstdlib>

#include "support/command.h"
#include "support/temp_directory.h"

TEST(WindowCancelButton, AClickOnCancelStopsALongRunAndTheWindowStays) {
  if (std::system("command -v xdotool >/dev/null && command -v xvfb-run >/dev/null") != 0)
    GTEST_SKIP() << "xdotool or xvfb-run is not installed (scripts/setup.sh installs both)";
  const TempDirectory dir("penumbra_cancel_button");
  const CommandResult result = runShell("xvfb-run -a -s '-screen 0 1280x800x24' bash " PENUMBRA_SOURCE_DIR
                             "/tests/window/real_input_cancel.sh " + penumbraBinary() + " " +
                             dir.path().string());
  EXPECT_EQ(result.exitCode, 0) << result.output;
  EXPECT_EQ(result.output.find("FAILED"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("overlay shown after"), std::string::npos) << result.output;
  // Stopped by the click, between two SSM tiles.
  EXPECT_NE(result.output.find("cancelled in ssm after"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("(Cancel clicked)"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("alive after cancel"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("exit 0"), std::string::npos) << result.output;
}

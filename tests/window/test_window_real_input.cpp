// The window under real X input events (xdotool on a private Xvfb, driven by
// tests/window/real_input_combo.sh), as a user clicks: entries of a view's output drop-down
// that lie over the image are picked one after another (a downstream output after an
// upstream one, which the demand-driven run has not computed yet); the window stays open,
// shows each output picked, ignores Esc and closes on Ctrl+Q with status 0.
#include <gtest/gtest.h>

#include <cstdlib>
#include <regex>

#include "support/command.h"
#include "support/gl_test.h"
#include "support/temp_directory.h"
#include "window/ui_session.h"

namespace {

int count(const std::string& text, const std::regex& pattern) {
  return int(std::distance(std::sregex_iterator(text.begin(), text.end(), pattern), std::sregex_iterator()));
}

}  // namespace

TEST(WindowRealInput, OutputsPickedOverTheImageKeepTheWindowOpen) {
  if (std::system("command -v xdotool >/dev/null && command -v xvfb-run >/dev/null") != 0)
    GTEST_SKIP() << "xdotool or xvfb-run is not installed (scripts/setup.sh installs both)";
  headlessContext();
  Session session;  // the drop-down lists every declared output in pipeline order
  std::string outputs;
  for (const std::string& key : session.outputKeys()) outputs += key + " ";
  const TempDirectory dir("penumbra_real_input");
  // Each pair: an upstream output, then one the run for it did not compute.
  const std::string pairs =
      "gbuffer.albedo>composite.color light_layers.near>composite.color classify.mask>trace.visibility";
  const CommandResult result = runShell("xvfb-run -a -s '-screen 0 1280x800x24' bash " PENUMBRA_SOURCE_DIR
                         "/tests/window/real_input_combo.sh " + penumbraBinary() + " " +
                         dir.path().string() + " '" + outputs + "' '" + pairs + "'");
  EXPECT_EQ(result.exitCode, 0) << result.output;
  EXPECT_EQ(result.output.find("FAILED"), std::string::npos) << result.output;
  // The downstream picks lay over the image, as in the report, and each was shown.
  EXPECT_EQ(count(result.output, std::regex("shown composite\\.color at [0-9]+ [0-9]+ \\(over the image: yes\\)")), 2)
      << result.output;
  EXPECT_EQ(count(result.output, std::regex("shown trace\\.visibility at [0-9]+ [0-9]+ \\(over the image: yes\\)")), 1)
      << result.output;
  EXPECT_NE(result.output.find("alive after Esc"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("exit 0"), std::string::npos) << result.output;
  EXPECT_EQ(result.output.find("has not been written"), std::string::npos) << result.output;
}

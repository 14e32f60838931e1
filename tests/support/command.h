// Runs the penumbra binary (PENUMBRA_BINARY) with arguments; captures stdout+stderr.
#pragma once
#include <string>

struct CommandResult {
  int exitCode;
  std::string output;
};
// Runs a shell command line (popen); captures stdout+stderr and the exit status.
CommandResult runShell(const std::string& command);
CommandResult runPenumbra(const std::string& arguments);
// The path of the penumbra executable under test.
std::string penumbraBinary();

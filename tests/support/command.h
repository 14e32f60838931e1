// Runs the penumbra binary (PENUMBRA_BINARY) with arguments; captures stdout+stderr.
#pragma once
#include <string>

struct CommandResult {
  int exitCode;
  std::string output;
};
CommandResult runPenumbra(const std::string& arguments);
// The penumbra binary's path (for tests that start it themselves).
std::string runPenumbraBinary();

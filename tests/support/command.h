// Runs the penumbra binary (PENUMBRA_BINARY) with arguments; captures stdout+stderr.
#pragma once
#include <string>

struct CommandResult {
  int exitCode;
  std::string output;
};
CommandResult runPenumbra(const std::string& arguments);
// The path of the penumbra executable under test.
std::string penumbraBinary();

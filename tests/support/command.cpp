#include "command.h"

#include <array>
#include <cstdio>
#include <sys/wait.h>

CommandResult runShell(const std::string& command) {
  CommandResult result{-1, ""};
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer;
  while (size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) result.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

CommandResult runPenumbra(const std::string& arguments) {
  // PENUMBRA_GL_ERRORS_FATAL=1: a GL error ends the run with status 3 (app/gl/gl_context.h).
  return runShell("PENUMBRA_GL_ERRORS_FATAL=1 " + std::string(PENUMBRA_BINARY_PATH) + " " +
                  arguments);
}

std::string penumbraBinary() { return PENUMBRA_BINARY_PATH; }

#include "io/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "core/run_control.h"

extern char** environ;

namespace {

constexpr size_t kKeptBytes = 16 * 1024;

int exitStatusOf(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

// Ends the child: SIGTERM, then SIGKILL if it is still there after 2 s; always reaped.
void endChild(pid_t pid) {
  ::kill(pid, SIGTERM);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  int status = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(pid, &status, WNOHANG) == pid) return;
    ::usleep(20 * 1000);
  }
  ::kill(pid, SIGKILL);
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
}

}  // namespace

std::string findExecutable(const std::string& name) {
  if (name.empty()) return "";
  auto executable = [](const std::string& path) {
    struct stat info {};
    return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode) && ::access(path.c_str(), X_OK) == 0;
  };
  if (name.find('/') != std::string::npos) return executable(name) ? name : "";
  const char* path = std::getenv("PATH");
  if (!path) return "";
  const std::string list = path;
  for (size_t start = 0; start <= list.size();) {
    size_t end = list.find(':', start);
    if (end == std::string::npos) end = list.size();
    const std::string directory = end > start ? list.substr(start, end - start) : ".";
    const std::string candidate = directory + "/" + name;
    if (executable(candidate)) return candidate;
    start = end + 1;
  }
  return "";
}

ChildResult runChild(const std::vector<std::string>& argv) {
  if (argv.empty()) throw std::runtime_error("runChild: no program");
  const std::string program = findExecutable(argv[0]);
  if (program.empty()) throw std::runtime_error(argv[0] + ": not found on PATH");
  int pipeEnds[2];
  if (::pipe2(pipeEnds, O_CLOEXEC) != 0)
    throw std::runtime_error(std::string("cannot run ") + argv[0] + ": pipe: " + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, pipeEnds[1], 2);
  // The child starts with default signal handling (the export's Ctrl-C handler is ours).
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults, none;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  sigaddset(&defaults, SIGPIPE);
  sigemptyset(&none);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  std::vector<char*> args;
  for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = ::posix_spawn(&pid, program.c_str(), &actions, &attributes, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(pipeEnds[1]);
  if (spawned != 0) {
    ::close(pipeEnds[0]);
    throw std::runtime_error("cannot run " + program + ": " + std::strerror(spawned));
  }
  ChildResult result;
  bool open = true;
  char buffer[4096];
  for (;;) {
    pollRunCancel();  // the CLI's Ctrl-C, the window's Esc and Cancel (core/run_control.h)
    if (runCancelRequested()) {
      ::close(pipeEnds[0]);
      endChild(pid);
      throw RunCancelled("cancelled while " + program + " ran (" + runCancelReason() + ")");
    }
    if (open) {
      pollfd entry{pipeEnds[0], POLLIN, 0};
      const int ready = ::poll(&entry, 1, 50);
      if (ready > 0) {
        const ssize_t got = ::read(pipeEnds[0], buffer, sizeof buffer);
        if (got > 0) {
          result.errorOutput.append(buffer, size_t(got));
          if (result.errorOutput.size() > 2 * kKeptBytes)
            result.errorOutput.erase(0, result.errorOutput.size() - kKeptBytes);
        } else if (got == 0 || errno != EINTR) {
          open = false;
        }
      }
    } else {
      ::usleep(20 * 1000);
    }
    int status = 0;
    const pid_t waited = ::waitpid(pid, &status, WNOHANG);
    if (waited == pid) {
      // What it wrote before it ended.
      while (open) {
        const ssize_t got = ::read(pipeEnds[0], buffer, sizeof buffer);
        if (got > 0) result.errorOutput.append(buffer, size_t(got));
        else if (got == 0 || errno != EINTR) open = false;
      }
      ::close(pipeEnds[0]);
      if (result.errorOutput.size() > kKeptBytes)
        result.errorOutput.erase(0, result.errorOutput.size() - kKeptBytes);
      result.exitStatus = exitStatusOf(status);
      return result;
    }
  }
}

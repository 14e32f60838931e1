#include "stats/dieharder_run.h"

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

std::vector<DieharderLine> parseDieharderOutput(const std::string& text) {
  std::vector<DieharderLine> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, '|');) {
      const size_t begin = cell.find_first_not_of(" \t"), end = cell.find_last_not_of(" \t\r");
      fields.push_back(begin == std::string::npos ? "" : cell.substr(begin, end - begin + 1));
    }
    if (fields.size() != 6 || fields[0].empty() || fields[0][0] == '#') continue;
    char* numberEnd = nullptr;
    const double p = std::strtod(fields[4].c_str(), &numberEnd);
    if (numberEnd == fields[4].c_str() || *numberEnd != '\0') continue;  // the header line
    lines.push_back({fields[0], std::atoi(fields[1].c_str()), p, fields[5]});
  }
  return lines;
}

std::vector<int> diehardTests() { return {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 15, 16}; }

std::string findDieharder() {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::filesystem::path candidate = std::filesystem::path(dir) / "dieharder";
    if (!dir.empty() && access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

int thesisDiehardPasses(const std::string& hash) {
  if (hash == "md5_16") return 11;
  if (hash == "md5_64") return 12;
  if (hash == "lcg15") return 6;  // the thesis's C rand()
  return -1;
}

DieharderRun::DieharderRun(std::string penumbra, std::string hash, std::vector<int> tests,
                           std::uint32_t key)
    : penumbra_(std::move(penumbra)), hash_(std::move(hash)), tests_(std::move(tests)), key_(key) {}

DieharderRun::~DieharderRun() {
  cancel();
  if (thread_.joinable()) thread_.join();
}

void DieharderRun::start() { thread_ = std::thread([this] { work(); }); }

void DieharderRun::cancel() {
  cancel_ = true;
  if (const int group = childGroup_; group > 0) kill(-group, SIGTERM);
}

std::vector<DieharderLine> DieharderRun::lines() const {
  std::lock_guard lock(mutex_);
  return lines_;
}

std::string DieharderRun::error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

void DieharderRun::work() {
  for (int test : tests_) {
    if (cancel_) break;
    // 1. The pipeline in a shell of its own process group: the stream ends when dieharder
    // has read enough (penumbra hash treats the closed pipe as the end).
    const std::string command = "exec 2>/dev/null; '" + penumbra_ + "' hash --hash " + hash_ +
                                " --key " + std::to_string(key_) + " --count 4294967295 | dieharder -g 200 -d " +
                                std::to_string(test);
    int pipeFds[2];
    if (pipe(pipeFds) != 0) break;
    const pid_t child = fork();
    if (child == 0) {
      setpgid(0, 0);
      dup2(pipeFds[1], STDOUT_FILENO);
      close(pipeFds[0]);
      close(pipeFds[1]);
      execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    close(pipeFds[1]);
    if (child < 0) {
      close(pipeFds[0]);
      std::lock_guard lock(mutex_);
      error_ = "could not start dieharder";
      break;
    }
    setpgid(child, child);
    childGroup_ = child;
    if (cancel_) kill(-child, SIGTERM);
    // 2. Read everything, then parse the test's result lines.
    std::string output;
    char buffer[4096];
    for (ssize_t n; (n = read(pipeFds[0], buffer, sizeof buffer)) > 0;) output.append(buffer, size_t(n));
    close(pipeFds[0]);
    int status = 0;
    waitpid(child, &status, 0);
    childGroup_ = 0;
    if (cancel_) break;
    const auto parsed = parseDieharderOutput(output);
    std::lock_guard lock(mutex_);
    if (parsed.empty()) error_ = "dieharder -d " + std::to_string(test) + " printed no result";
    lines_.insert(lines_.end(), parsed.begin(), parsed.end());
    ++testsDone_;
  }
  finished_ = true;
}

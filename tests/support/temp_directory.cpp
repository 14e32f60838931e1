#include "support/temp_directory.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <vector>

namespace fs = std::filesystem;

TempDirectory::TempDirectory(const std::string& name) {
  std::string pattern = (fs::temp_directory_path() / (name + "_XXXXXX")).string();
  if (!::mkdtemp(pattern.data()))
    throw std::runtime_error("mkdtemp " + pattern + ": " + std::strerror(errno));
  path_ = pattern;
}

TempDirectory::~TempDirectory() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

std::string TempDirectory::write(const std::string& name, const std::string& bytes) const {
  const fs::path file = path_ / name;
  std::ofstream(file, std::ios::binary) << bytes;
  return file.string();
}

namespace {

// The directories scratchDirectory() handed out, removed when the test process exits.
struct ScratchDirectories {
  const pid_t owner = ::getpid();
  std::vector<std::unique_ptr<TempDirectory>> directories;
  ~ScratchDirectories() {
    if (::getpid() != owner)  // a forked child exiting normally must not remove the parent's
      for (auto& directory : directories) (void)directory.release();
  }
};

}  // namespace

fs::path scratchDirectory(const std::string& name) {
  static ScratchDirectories scratch;
  scratch.directories.push_back(std::make_unique<TempDirectory>("penumbra_" + name));
  return scratch.directories.back()->path();
}

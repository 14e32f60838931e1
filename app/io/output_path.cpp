#include "io/output_path.h"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/input_error.h"

namespace fs = std::filesystem;

namespace {

std::string shown(const fs::path& path) {
  std::string text(1, '\'');
  text += printable(path.string(), 200);
  text += '\'';
  return text;
}

// 1. The nearest ancestor that exists must be a directory we can write into.
void checkParent(const fs::path& path, const std::string& flag) {
  fs::path ancestor = fs::absolute(path).parent_path();
  std::error_code error;
  while (!fs::exists(ancestor, error) && ancestor.has_parent_path() &&
         ancestor != ancestor.parent_path())
    ancestor = ancestor.parent_path();
  if (!fs::is_directory(ancestor, error))
    throw InputError(flag + " " + shown(path) + ": cannot create it: " + shown(ancestor) +
                     " is not a directory");
  if (::access(ancestor.c_str(), W_OK | X_OK) != 0)
    throw InputError(flag + " " + shown(path) + ": cannot create it: " + shown(ancestor) +
                     ": " + std::strerror(errno));
}

bool processAlive(long pid) { return pid > 0 && (::kill(pid_t(pid), 0) == 0 || errno == EPERM); }

}  // namespace

void checkOutputFile(const fs::path& file, const std::string& flag) {
  std::error_code error;
  if (file.empty()) throw InputError(flag + ": empty path");
  if (fs::is_directory(file, error))
    throw InputError(flag + " " + shown(file) + " is a directory; expected a file name");
  checkParent(file, flag);
}

void checkOutputDirectory(const fs::path& directory, const std::string& flag,
                          const std::string& marker) {
  std::error_code error;
  if (directory.empty()) throw InputError(flag + ": empty path");
  if (fs::exists(directory, error)) {
    if (!fs::is_directory(directory, error))
      throw InputError(flag + " " + shown(directory) + " exists and is not a directory");
    if (!marker.empty() && !fs::is_empty(directory, error) && !fs::exists(directory / marker, error))
      throw InputError(flag + " " + shown(directory) + " is a non-empty directory without " +
                       marker + " (not an earlier output): it would be replaced as a whole; "
                       "choose a new or empty directory");
  }
  checkParent(directory, flag);
}

// 2. The transaction.
DirectoryTransaction::DirectoryTransaction(const fs::path& target)
    : target_(fs::absolute(target).lexically_normal()) {
  if (!target_.has_filename()) target_ = target_.parent_path();  // "out/" -> "out"
  const fs::path parent = target_.parent_path();
  fs::create_directories(parent);
  const std::string prefix = std::string(".").append(target_.filename().string()).append(".partial-");
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(parent, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) == 0 && !processAlive(std::atol(name.c_str() + prefix.size())))
      fs::remove_all(entry.path(), error);  // a killed export's leftovers
  }
  temporary_ = parent / (prefix + std::to_string(::getpid()));
  fs::remove_all(temporary_);
  fs::create_directory(temporary_);
}

DirectoryTransaction::~DirectoryTransaction() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove_all(temporary_, ignored);
}

void DirectoryTransaction::commit() {
  std::error_code error;
  if (fs::exists(target_, error)) {
    if (::renameat2(AT_FDCWD, temporary_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) != 0)
      throw std::runtime_error("cannot replace " + target_.string() + ": " + std::strerror(errno));
    committed_ = true;
    fs::remove_all(temporary_, error);  // now the previous export
    return;
  }
  fs::rename(temporary_, target_);
  committed_ = true;
}

void DirectoryTransaction::commitFiles(const std::string& last) {
  fs::create_directories(target_);
  for (const auto& entry : fs::directory_iterator(temporary_))
    if (entry.path().filename() != last)
      fs::rename(entry.path(), target_ / entry.path().filename());
  if (fs::exists(temporary_ / last)) fs::rename(temporary_ / last, target_ / last);
  committed_ = true;
  fs::remove_all(temporary_);
}

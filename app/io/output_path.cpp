#include "io/output_path.h"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "base/input_error.h"

namespace fs = std::filesystem;

namespace {

std::string shown(const fs::path& path) {
  std::string text(1, '\'');
  text += printable(path.string(), 200);
  text += '\'';
  return text;
}

// 1. The nearest ancestor that exists must be a directory we can create files in: tried
//    with a probe file (access() says yes to root on /proc and says nothing of quotas).
void checkParent(const fs::path& path, const std::string& flag) {
  fs::path ancestor = fs::absolute(path).parent_path();
  std::error_code error;
  while (!fs::exists(ancestor, error) && ancestor.has_parent_path() &&
         ancestor != ancestor.parent_path())
    ancestor = ancestor.parent_path();
  if (!fs::is_directory(ancestor, error))
    throw InputError(flag + " " + shown(path) + ": cannot create it: " + shown(ancestor) +
                     " is not a directory");
  const fs::path probe = ancestor / (".penumbra-probe-" + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0)
    throw InputError(flag + " " + shown(path) + ": cannot create it in " + shown(ancestor) +
                     ": " + std::strerror(errno));
  ::close(fd);
  ::unlink(probe.c_str());
}

bool processAlive(long pid) { return pid > 0 && (::kill(pid_t(pid), 0) == 0 || errno == EPERM); }

// 2. Temporaries `<prefix><pid>...` in `parent` whose process is gone.
void removeLeftovers(const fs::path& parent, const std::string& prefix) {
  std::error_code error;
  if (!fs::is_directory(parent, error)) return;
  for (const auto& entry : fs::directory_iterator(parent, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) == 0 && !processAlive(std::atol(name.c_str() + prefix.size())))
      fs::remove_all(entry.path(), error);  // a killed run's leftovers
  }
}

fs::path normalTarget(const fs::path& target) {
  fs::path normal = fs::absolute(target).lexically_normal();
  if (!normal.has_filename()) normal = normal.parent_path();  // "out/" -> "out"
  return normal;
}

std::string directoryPrefix(const fs::path& target) {
  return std::string(".").append(target.filename().string()).append(".partial-");
}

std::string filePrefix(const fs::path& file) {
  return std::string(".").append(file.stem().string()).append(".partial-");
}

}  // namespace

void checkOutputFile(const fs::path& file, const std::string& flag) {
  std::error_code error;
  if (file.empty()) throw InputError(flag + ": empty path");
  if (fs::is_directory(file, error))
    throw InputError(flag + " " + shown(file) + " is a directory; expected a file name");
  if (fs::exists(file, error) && !fs::is_regular_file(file, error))
    throw InputError(flag + " " + shown(file) + " exists and is not a regular file");
  checkParent(file, flag);
  removeLeftovers(fs::absolute(file).parent_path(), filePrefix(file));
}

void checkOutputDirectory(const fs::path& directory, const std::string& flag,
                          const std::string& manifest) {
  std::error_code error;
  if (directory.empty()) throw InputError(flag + ": empty path");
  if (fs::exists(directory, error)) {
    if (!fs::is_directory(directory, error))
      throw InputError(flag + " " + shown(directory) + " exists and is not a directory");
    if (!manifest.empty() && !fs::is_empty(directory, error) && !fs::exists(directory / manifest, error))
      throw InputError(flag + " " + shown(directory) + " is a non-empty directory without " +
                       manifest + " (not an earlier output of this command): it would be "
                       "replaced as a whole, so it is left alone; choose a new or empty directory");
  }
  checkParent(directory, flag);
  const fs::path target = normalTarget(directory);
  removeLeftovers(target.parent_path(), directoryPrefix(target));
}

fs::path temporaryFileName(const fs::path& path) {
  return path.parent_path() /
         (filePrefix(path) + std::to_string(::getpid()) + path.extension().string());
}

std::string writeFailure(const fs::path& path, int savedErrno, const std::string& detail) {
  std::string reason;
  if (savedErrno == ENOSPC || savedErrno == EDQUOT || savedErrno == EROFS || savedErrno == EIO ||
      savedErrno == EACCES || savedErrno == EPERM || savedErrno == EFBIG)
    reason = std::strerror(savedErrno);
  else {
    // Image libraries keep their own messages ("Failed OpenEXR write"); ask the file
    // system why.
    const fs::path parent = fs::absolute(path).parent_path();
    struct statvfs info {};
    if (::statvfs(parent.c_str(), &info) == 0) {
      if (info.f_flag & ST_RDONLY) reason = std::strerror(EROFS);
      else if (info.f_bavail == 0 || info.f_favail == 0) reason = std::strerror(ENOSPC);
    }
  }
  if (reason.empty()) reason = detail.empty() ? std::string("write failed") : detail;
  else if (!detail.empty() && detail != reason) reason += " (" + detail + ")";
  return "cannot write " + path.string() + ": " + reason;
}

std::string checkScriptPath(const std::string& path, bool underExportDirectory) {
  if (path.empty()) return "an empty path";
  const fs::path p(path);
  for (const auto& part : p)
    if (part == "..")
      return "a path with '..' (writes stay inside the export folder; name a file or folder in it)";
  if (underExportDirectory && p.is_absolute())
    return "an absolute path (with an export folder, every path is relative to it)";
  return "";
}

// 3. The transaction.
DirectoryTransaction::DirectoryTransaction(const fs::path& target, std::string manifest)
    : target_(normalTarget(target)), manifest_(std::move(manifest)) {
  const fs::path parent = target_.parent_path();
  fs::create_directories(parent);
  const std::string prefix = directoryPrefix(target_);
  removeLeftovers(parent, prefix);
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
  if (!manifest_.empty()) checkOutputDirectory(target_, "the output", manifest_);
  if (fs::exists(target_, error)) {
    if (::renameat2(AT_FDCWD, temporary_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) != 0)
      throw std::runtime_error("cannot replace " + target_.string() + ": " + std::strerror(errno));
    committed_ = true;
    fs::remove_all(temporary_, error);  // now the previous output
    return;
  }
  fs::rename(temporary_, target_);
  committed_ = true;
}

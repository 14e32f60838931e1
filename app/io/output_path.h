// Output paths are checked before any rendering (a bad --out is bad input: InputError,
// exit 2, nothing computed), and an output directory is written as a transaction: into a
// hidden temporary sibling, then renamed into place in one step, so a failed, cancelled
// or killed export leaves the previous one intact and never a mix of old and new files.
#pragma once
#include <filesystem>
#include <string>

// A file we may create or replace: not a directory, and its parent exists or can be
// created (the nearest existing ancestor is a writable directory). Throws InputError.
void checkOutputFile(const std::filesystem::path& file, const std::string& flag);
// A directory we may replace as a whole: absent, empty, or an earlier output of ours
// (holding `marker`, e.g. run.json); its parent as for checkOutputFile. With an empty
// `marker`, any directory (files are added to it, see commitFiles). Throws InputError.
void checkOutputDirectory(const std::filesystem::path& directory, const std::string& flag,
                          const std::string& marker);

class DirectoryTransaction {
public:
  // Creates `<parent>/.<name>.partial-<pid>` (and `parent` if missing); removes the
  // leftovers of transactions whose process is gone.
  explicit DirectoryTransaction(const std::filesystem::path& target);
  ~DirectoryTransaction();  // not committed: the temporary directory is removed
  DirectoryTransaction(const DirectoryTransaction&) = delete;
  DirectoryTransaction& operator=(const DirectoryTransaction&) = delete;

  const std::filesystem::path& path() const { return temporary_; }  // write here
  const std::filesystem::path& target() const { return target_; }
  // Swaps the temporary directory into place atomically (renameat2 RENAME_EXCHANGE when
  // the target exists), then removes the previous contents.
  void commit();
  // For a directory shared with other files (bench results): moves each file into the
  // target (created if missing), `last` last, so the previous set stays whole until the
  // rendering is done and `last` (the report naming the others) marks a complete set.
  void commitFiles(const std::string& last);

private:
  std::filesystem::path target_, temporary_;
  bool committed_ = false;
};

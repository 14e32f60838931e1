// One output rule for every writer (export, bench, trace, hash-stats, lessons, scripts, the
// window's export buttons):
// - a path is checked before any work (a bad one is bad input: InputError, exit 2): its
//   nearest existing ancestor must be a directory we can create files in (tried, not
//   guessed from permission bits: root, read-only mounts and /proc answer differently);
// - an existing directory is replaced only when it holds a previous output of the same
//   writer, recognised by that writer's manifest (run.json, results.json, lesson.md, ...);
//   any other non-empty directory is refused, never emptied;
// - a multi-file output is a transaction: written into the hidden temporary sibling
//   `.<name>.partial-<pid>`, manifest last, then renamed into place in one step, so a
//   failed, cancelled or killed run leaves the previous output intact and never a mix;
// - leftovers of killed runs (temporaries whose process is gone) are removed when the next
//   run checks or opens the same output;
// - a failed write names the OS reason ("No space left on device").
#pragma once
#include <filesystem>
#include <stdexcept>
#include <string>

// A file we may create or replace: not a directory, and its parent exists or can be
// created. Removes dead runs' temporaries of this file. Throws InputError.
void checkOutputFile(const std::filesystem::path& file, const std::string& flag);
// A directory we may replace as a whole: absent, empty, or an earlier output of ours
// (holding `manifest`, e.g. run.json); its parent as for checkOutputFile. With an empty
// `manifest`, any directory (files are added to it one by one). Removes dead runs'
// temporaries of this directory. Throws InputError.
void checkOutputDirectory(const std::filesystem::path& directory, const std::string& flag,
                          const std::string& manifest);

// The temporary name a single file is written under before its rename:
// "dir/.name.partial-<pid>.ext" (same extension, so image writers pick the same format).
std::filesystem::path temporaryFileName(const std::filesystem::path& path);
// A write the file system refused (full, read-only, gone): not bad input, not a bug in
// penumbra either; main() prints its message without "internal error" and exits 1.
struct WriteError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// "cannot write PATH: REASON" where REASON is the OS's (errno, else what the file system
// says: no space left, read-only), falling back to `detail` (a library's message).
std::string writeFailure(const std::filesystem::path& path, int savedErrno, const std::string& detail);

// A path a script or lesson writes (README "Scripts and lessons"): "" or why not. Never
// "..": writes stay inside the folder the user named; with an export folder
// (`underExportDirectory`), never absolute either: every path is relative to it.
std::string checkScriptPath(const std::string& path, bool underExportDirectory);

class DirectoryTransaction {
public:
  // Creates `<parent>/.<name>.partial-<pid>` (and `parent` if missing); removes the
  // leftovers of transactions whose process is gone. `manifest`: see commit().
  explicit DirectoryTransaction(const std::filesystem::path& target, std::string manifest = "");
  ~DirectoryTransaction();  // not committed: the temporary directory is removed
  DirectoryTransaction(const DirectoryTransaction&) = delete;
  DirectoryTransaction& operator=(const DirectoryTransaction&) = delete;

  const std::filesystem::path& path() const { return temporary_; }  // write here
  const std::filesystem::path& target() const { return target_; }
  // Swaps the temporary directory into place atomically (renameat2 RENAME_EXCHANGE when
  // the target exists), then removes the previous contents. With a `manifest`, the target
  // is checked again first (checkOutputDirectory): a directory that became someone else's
  // meanwhile is never replaced.
  void commit();

private:
  std::filesystem::path target_, temporary_;
  std::string manifest_;
  bool committed_ = false;
};

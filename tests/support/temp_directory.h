// Scratch directories for tests. Every one has a unique name (mkdtemp), so tests running in
// parallel (ctest -j) and two checkouts testing at once never share one, and every one is
// removed with its contents afterwards.
#pragma once
#include <filesystem>
#include <string>

class TempDirectory {
public:
  explicit TempDirectory(const std::string& name);  // <tmp>/<name>_XXXXXX, created empty
  ~TempDirectory();                                 // removes it and everything in it
  TempDirectory(const TempDirectory&) = delete;
  TempDirectory& operator=(const TempDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::string write(const std::string& name, const std::string& bytes) const;  // the path

private:
  std::filesystem::path path_;
};

// <tmp>/penumbra_<name>_XXXXXX for tests that need only a path: kept until the test process
// exits, then removed (by the process that made it, not by a forked child).
std::filesystem::path scratchDirectory(const std::string& name);

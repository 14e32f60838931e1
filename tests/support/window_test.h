// Helpers for the window tests that run `penumbra --script` under Xvfb.
#pragma once
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#define REQUIRE_DISPLAY() \
  if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY: run under xvfb-run (make test does)"

// A fresh directory under the system temp directory for one test.
std::filesystem::path scratchDirectory(const std::string& name);
// Writes `json` to <directory>/script.json and returns the path.
std::filesystem::path writeScript(const std::filesystem::path& directory, const std::string& json);

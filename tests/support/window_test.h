// Helpers for the window tests that run `penumbra --script` under Xvfb.
#pragma once
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/temp_directory.h"  // scratchDirectory

#define REQUIRE_DISPLAY() \
  if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY: run under xvfb-run (make test does)"

// Writes `json` to <directory>/script.json and returns the path.
std::filesystem::path writeScript(const std::filesystem::path& directory, const std::string& json);

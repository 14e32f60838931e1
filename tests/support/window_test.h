// Helpers for the window tests that run `penumbra --script` under Xvfb.
#pragma once
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "support/command.h"         // CommandResult
#include "support/temp_directory.h"  // scratchDirectory

#define REQUIRE_DISPLAY() \
  if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY: run under xvfb-run (make test does)"

// Writes `json` to <directory>/script.json and returns the path.
std::filesystem::path writeScript(const std::filesystem::path& directory, const std::string& json);

// Plays `lessonFile` through with `penumbra lesson <file> --export <exportDir>`: success when
// it exits 0, prints "lesson step <steps>/<steps>" and every file of `figures` exists in
// exportDir. The run's exit status and output go to *result when given.
// Use as ASSERT_TRUE(playLesson(...)).
::testing::AssertionResult playLesson(const std::string& lessonFile, int steps,
                                      const std::vector<std::string>& figures,
                                      const std::filesystem::path& exportDir,
                                      CommandResult* result = nullptr);

// The eye pixel (image coordinates: row 0 at the top) of the first penumbra pixel past the
// middle of the classify mask that `penumbra export` writes at 160 x 120 into
// <directory>/cli (default cube scene; EXR rows are GL order) whose rays all reach the
// search (no early out counted in trace.cost's channel "earlyOuts"): a penumbra pixel on a
// face that sees only part of the light may end every ray at the back-face test and show no
// points. False when the export fails or no pixel qualifies.
bool penumbraPixel(const std::filesystem::path& directory, int& x, int& y);

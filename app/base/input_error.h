// Bad input (a file, a scene, a flag, a parameter value, an output path) is something the
// user can fix: it throws InputError, and main() turns it into its message and exit status
// 2. Every other exception is an internal failure: its message and exit status 1
// (app/cli/main.cpp). Untrusted text (keys, names, paths from files) goes into messages
// through printable(): bounded in length, control characters escaped.
#pragma once
#include <stdexcept>
#include <string>

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// At most `maxBytes` bytes of `text`, control bytes (ANSI escapes, newlines) as \xNN, and
// "... (N bytes)" when cut; no surrounding quotes.
std::string printable(const std::string& text, size_t maxBytes = 80);

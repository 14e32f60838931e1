// One reader rule for every JSON file a user hands penumbra (scene, settings, script,
// lesson): a regular file (a FIFO, device or directory is refused before anything is read,
// so nothing hangs), at most kMaxJsonBytes, nested at most kMaxJsonDepth deep, no string or
// key longer than kMaxJsonString, no key given twice in an object. Problems are InputError
// "<file>: <JSON pointer>: <problem>" (or "<file>: not valid JSON: <where, what>"), with
// keys and values cut and control characters escaped (printable(), base/input_error.h).
// The limits are checked by a SAX pass before the document is built, so a hostile file
// never reaches code that recurses over the document (dump, copy, comparison).
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

inline constexpr std::uintmax_t kMaxJsonBytes = std::uintmax_t(16) << 20;  // 16 MiB
inline constexpr int kMaxJsonDepth = 64;
inline constexpr size_t kMaxJsonString = 4096;  // a lesson's longest text is 1,137 bytes

// "" when `path` is a regular file, else why not: "no such file", "a FIFO (named pipe), not
// a regular file", "a directory, ...", "a character device, ...", or the OS reason ("Too
// many levels of symbolic links"). Nothing is opened.
std::string regularFileProblem(const std::string& path);

// The bytes of `path`, a regular file of at most `maxBytes` bytes. Throws InputError
// "<path>: <why>" (no such file, a FIFO, a directory, a device, too large, the OS reason).
std::string readInputFile(const std::string& path, std::uintmax_t maxBytes = kMaxJsonBytes);

// Parses `text` under the limits; `path` names it in messages.
nlohmann::json parseJsonText(const std::string& text, const std::string& path);
// readInputFile + parseJsonText.
nlohmann::json readJsonFile(const std::string& path);

// "<parent>/<key>" with RFC 6901 escaping (~0, ~1), the key through printable().
std::string jsonPointer(const std::string& parent, const std::string& key);
// A value for a message: its JSON text, cut to `maxBytes` (printable()).
std::string shortJson(const nlohmann::json& value, size_t maxBytes = 80);

// Text from a file for the terminal or a draw list: control characters other than newline
// and tab removed (an ESC, a BEL, a carriage return would act on the terminal), at most
// `maxBytes` bytes, cut at a UTF-8 character boundary with " ..." appended when cut.
std::string plainText(const std::string& text, size_t maxBytes);

// Small checks shared by the input tests: the message an input is refused with, whether a
// text holds a part, a file's text.
#pragma once
#include <filesystem>
#include <functional>
#include <string>

// The message of the InputError `load` throws. Another exception, or none, is a test failure
// naming `what` (then its message, or "").
std::string refusalOf(const std::string& what, const std::function<void()>& load);

bool contains(const std::string& text, const std::string& part);

// The whole file ("" when it cannot be read).
std::string readText(const std::filesystem::path& path);

// The shared part of the JSON readers' libFuzzer harnesses (fuzz_script.cpp, fuzz_lesson.cpp,
// fuzz_settings.cpp): the reader every script, lesson and settings file goes through
// (base/json_input.h: limits on size, depth, strings, repeated keys) on arbitrary bytes, the
// document copied and compared as actions and settings are, then every value visited with the
// harness's own check of each string. Every input must be read or refused with an InputError;
// anything else (a crash, a stack overflow, a sanitizer report, a hang) is a finding.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "base/input_error.h"
#include "base/json_input.h"

namespace fuzz_json {

// Every value, recursively (bounded by the reader's depth limit, or this overflows).
template <class OnString>
void visit(const nlohmann::json& value, const std::string& pointer, int depth, const OnString& onString) {
  if (depth > kMaxJsonDepth + 1) __builtin_trap();  // the reader let a deeper document through
  (void)shortJson(value);
  if (value.is_object())
    for (const auto& [key, item] : value.items())
      visit(item, jsonPointer(pointer, key), depth + 1, onString);
  else if (value.is_array())
    for (size_t i = 0; i < value.size(); ++i)
      visit(value[i], pointer + "/" + std::to_string(i), depth + 1, onString);
  else if (value.is_string()) {
    if (value.get<std::string>().size() > kMaxJsonString) __builtin_trap();
    onString(value.get<std::string>());
  }
}

template <class OnString>
int readAndVisit(const std::uint8_t* data, std::size_t size, const char* file, const OnString& onString) {
  try {
    const nlohmann::json root = parseJsonText(std::string(reinterpret_cast<const char*>(data), size), file);
    const nlohmann::json copy = root;
    if (!(copy == root)) __builtin_trap();
    visit(root, "", 0, onString);
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace fuzz_json

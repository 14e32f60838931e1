// libFuzzer harness (make fuzz, docs/reliability.md): the reader every settings file goes
// through (io/json_input.h: limits on size, depth, strings, repeated keys) on arbitrary
// bytes, then what the settings reader does with any document before its own checks:
// every key into a JSON pointer and every value into a message, as its checks
// report them. Every input must be read or refused with an
// InputError; anything else (a crash, a stack overflow, a sanitizer report, a hang) is a
// finding. The action table and applySettingsJson need the window and are not linked here.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/input_error.h"
#include "io/json_input.h"
#include "io/output_path.h"

using nlohmann::json;

namespace {

// Every value, recursively (bounded by the reader's depth limit, or this overflows).
void visit(const json& value, const std::string& pointer, int depth) {
  if (depth > kMaxJsonDepth + 1) __builtin_trap();  // the reader let a deeper document through
  (void)shortJson(value);
  if (value.is_object())
    for (const auto& [key, item] : value.items()) visit(item, jsonPointer(pointer, key), depth + 1);
  else if (value.is_array())
    for (size_t i = 0; i < value.size(); ++i) visit(value[i], pointer + "/" + std::to_string(i), depth + 1);
  else if (value.is_string()) {
    if (value.get<std::string>().size() > kMaxJsonString) __builtin_trap();
    (void)printable(value.get<std::string>());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const json root = parseJsonText(std::string(reinterpret_cast<const char*>(data), size),
                                    PENUMBRA_FUZZ_SEEDS "/settings/input.json");
    const json copy = root;  // copied and compared as actions and settings are
    if (!(copy == root)) __builtin_trap();
    visit(root, "", 0);
  } catch (const InputError&) {
  }
  return 0;
}

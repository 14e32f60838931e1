// libFuzzer harness (make fuzz, docs/reliability.md): the reader every settings file goes
// through (base/json_input.h: limits on size, depth, strings, repeated keys) on arbitrary
// bytes, then what the settings reader does with any document before its own checks:
// every key into a JSON pointer and every value into a message, as its checks
// report them. Every input must be read or refused with an
// InputError; anything else (a crash, a stack overflow, a sanitizer report, a hang) is a
// finding. The action table and applySettingsJson need the window and are not linked here.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_json_reader.h"
#include "io/output_path.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto check = [](const std::string& text) {
    (void)printable(text);
  };
  return fuzz_json::readAndVisit(data, size, PENUMBRA_FUZZ_SEEDS "/settings/input.json", check);
}

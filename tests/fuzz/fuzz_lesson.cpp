// libFuzzer harness (make fuzz, docs/reliability.md): the reader every lesson file goes
// through (base/json_input.h: limits on size, depth, strings, repeated keys) on arbitrary
// bytes, then what the lesson reader does with any document before its own checks:
// the texts for the terminal and the lesson panel (plainText) and the paths of its
// figures through the output rule (checkScriptPath). Every input must be read or refused with an
// InputError; anything else (a crash, a stack overflow, a sanitizer report, a hang) is a
// finding. The action table and applySettingsJson need the window and are not linked here.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_json_reader.h"
#include "io/output_path.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto check = [](const std::string& text) {
    if (plainText(text, 6000).size() > 6004) __builtin_trap();
    (void)checkScriptPath(text, true);
  };
  return fuzz_json::readAndVisit(data, size, PENUMBRA_FUZZ_SEEDS "/lesson/input.json", check);
}

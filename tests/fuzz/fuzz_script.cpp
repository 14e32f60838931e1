// libFuzzer harness (make fuzz, docs/reliability.md): the reader every script file goes
// through (base/json_input.h: limits on size, depth, strings, repeated keys) on arbitrary
// bytes, then what the script reader does with any document before its own checks:
// one-key actions, their names and arguments into messages (cut), every string through the
// output rule for paths (checkScriptPath). Every input must be read or refused with an
// InputError; anything else (a crash, a stack overflow, a sanitizer report, a hang) is a
// finding. The action table and applySettingsJson need the window and are not linked here.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_json_reader.h"
#include "io/output_path.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto check = [](const std::string& text) {
    (void)checkScriptPath(text, false);
  };
  return fuzz_json::readAndVisit(data, size, PENUMBRA_FUZZ_SEEDS "/script/input.json", check);
}

// libFuzzer harness (make fuzz, docs/reliability.md): the scene JSON reader on arbitrary
// bytes. Every input must load or be refused with an InputError; anything else (a crash, a
// sanitizer report, a hang, another exception, memory past -rss_limit_mb) is a finding.
// Relative glTF paths resolve in the seed corpus, so the reader reaches the importer.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "scene/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> warnings;
  try {
    parseSceneFile(std::string(reinterpret_cast<const char*>(data), size),
                   PENUMBRA_FUZZ_SEEDS "/scene_json/input.json", warnings);
  } catch (const InputError&) {
  }
  return 0;
}

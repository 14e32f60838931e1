// libFuzzer harness (make fuzz, docs/reliability.md): the scene JSON reader on arbitrary
// bytes. Every input must load or be refused with an InputError; anything else (a crash, a
// sanitizer report, a hang, another exception, memory past -rss_limit_mb) is a finding.
// Relative glTF paths resolve in the seed corpus, so the reader reaches the importer.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "scene/animation.h"
#include "scene/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> warnings;
  try {
    const Scene scene = parseSceneFile(std::string(reinterpret_cast<const char*>(data), size),
                                       PENUMBRA_FUZZ_SEEDS "/scene_json/input.json", warnings);
    // The pose of an accepted file at a few times (scene/animation.h): no crash, no hang.
    for (double t : {-1.0, 0.0, 0.7, 1e6}) (void)posedSceneProblem(scene, t);
  } catch (const InputError&) {
  }
  return 0;
}

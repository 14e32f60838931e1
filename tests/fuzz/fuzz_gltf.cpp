// libFuzzer harness (make fuzz, docs/reliability.md): the glTF importer on arbitrary bytes,
// as a .glb when they start with the GLB magic "glTF", else as a .gltf. Every input must
// load or be refused with an InputError; anything else is a finding. External buffer URIs
// resolve in the seed corpus.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "scene/scene_gltf.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::vector<unsigned char> bytes(data, data + size);
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  std::vector<std::string> warnings;
  try {
    loadGltfFromMemory(bytes, binary ? PENUMBRA_FUZZ_SEEDS "/gltf/input.glb"
                                     : PENUMBRA_FUZZ_SEEDS "/gltf/input.gltf",
                       glm::mat4(1), warnings);
  } catch (const InputError&) {
  }
  return 0;
}

// What the glTF importer reads (app/scene/gltf_file_access.h): a buffer only at the
// byteLength its glTF declares and within the scene's budget of bytes read, never before
// checking; files that are not regular files say what they are.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "base/input_error.h"
#include "scene/scene_gltf.h"
#include "support/refusal.h"
#include "support/temp_directory.h"

namespace fs = std::filesystem;

namespace {

// One triangle whose positions are `buffers` buffers, each naming `uri` with `byteLength`
// (only the first is used by the accessor).
std::string triangleGltf(const std::string& uri, std::uint64_t byteLength, int buffers = 1) {
  std::string list;
  for (int i = 0; i < buffers; ++i)
    list += std::string(i ? ", " : "") + R"({"uri": ")" + uri + R"(", "byteLength": )" +
            std::to_string(byteLength) + "}";
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "min": [0, 0, 0], "max": [1, 1, 0]}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}], "buffers": [)" + list + "]}";
}

std::string refusal(const std::string& path, SceneBudget* budget = nullptr) {
  std::vector<std::string> warnings;
  return refusalOf(path, [&] { loadGltf(path, glm::mat4(1), warnings, budget); });
}

void writeTriangleBin(const fs::path& path) {
  const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(positions), sizeof positions);
}

}  // namespace

// A buffer declared as 36 bytes naming a 2 GiB (sparse) file read the whole file before
// "File size mismatch"; now it is refused unread, at once.
TEST(GltfReads, ABufferIsReadOnlyAtItsDeclaredLength) {
  const TempDirectory dir("penumbra_gltf_reads");
  const fs::path big = dir.path() / "big.bin";
  { std::ofstream touch(big); }
  fs::resize_file(big, std::uintmax_t(2) << 30);  // sparse: no disk used
  const std::string message = refusal(dir.write("small.gltf", triangleGltf("big.bin", 36)));
  EXPECT_TRUE(contains(message, "the glTF declares 36 bytes for it, the file holds 2147483648 (not read)"))
      << message;
  // The same triangle at the right length loads.
  writeTriangleBin(dir.path() / "ok.bin");
  std::vector<std::string> warnings;
  EXPECT_EQ(loadGltf(dir.write("ok.gltf", triangleGltf("ok.bin", 36)), glm::mat4(1), warnings).size(), 1u);
}

// One file named by 8 buffers reached 10.4 GiB: the bytes read per scene are bounded
// (here a budget of 100 bytes: the glTF itself, then two 36-byte buffers do not fit).
TEST(GltfReads, TheBytesReadPerSceneAreBounded) {
  const TempDirectory dir("penumbra_gltf_budget");
  writeTriangleBin(dir.path() / "t.bin");
  const std::string gltf = dir.write("eight.gltf", triangleGltf("t.bin", 36, 8));
  SceneBudget budget;
  budget.fileBytes = fs::file_size(gltf) + 40;
  const std::string message = refusal(gltf, &budget);
  EXPECT_TRUE(contains(message, "pass the scene's limit of 2048 MiB of glTF files and buffers")) << message;
  SceneBudget tight;
  tight.fileBytes = 10;
  EXPECT_TRUE(contains(refusal(gltf, &tight), "pass the scene's limit")) << refusal(gltf, &tight);
}

// A FIFO, directory, symlink loop or device said "no such file" or "File not found".
TEST(GltfReads, FilesThatAreNotRegularSayWhatTheyAre) {
  const TempDirectory dir("penumbra_gltf_kinds");
  const fs::path fifo = dir.path() / "f.glb";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_TRUE(contains(refusal(fifo.string()), "a FIFO (named pipe), not a regular file")) << refusal(fifo.string());
  fs::create_directories(dir.path() / "d.glb");
  EXPECT_TRUE(contains(refusal((dir.path() / "d.glb").string()), "a directory, not a regular file"));
  fs::create_symlink("loop.glb", dir.path() / "loop.glb");
  EXPECT_TRUE(contains(refusal((dir.path() / "loop.glb").string()), "Too many levels of symbolic links"))
      << refusal((dir.path() / "loop.glb").string());
  EXPECT_TRUE(contains(refusal((dir.path() / "none.glb").string()), "no such file"));
  std::string up;
  for (int i = 0; i < 32; ++i) up += "../";
  const std::string zero = refusal(dir.write("zero.gltf", triangleGltf(up + "dev/zero", 36)));
  EXPECT_TRUE(contains(zero, "a character device, not a regular file")) << zero;
  EXPECT_FALSE(contains(zero, "File not found")) << zero;
}

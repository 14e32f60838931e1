// A researcher's model on the command line: a Draco-compressed file is refused with exit 2
// naming the extension; a loaded model's size is printed on stderr and kept in run.json.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "export/trace_json.h"
#include "support/command.h"
#include "support/temp_directory.h"

namespace fs = std::filesystem;

TEST(CliModel, DracoFileExits2NamingTheExtension) {
  const std::string draco = "/usr/share/assimp/models/glTF2/draco/2CylinderEngine.gltf";
  ASSERT_TRUE(fs::exists(draco)) << "install assimp-testmodels (scripts/setup.sh)";
  const TempDirectory dir("penumbra_cli_draco");
  const auto result = runPenumbra("export --scene " + draco + " --out " + (dir.path() / "out").string());
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("2CylinderEngine.gltf: Draco-compressed meshes "
                               "(KHR_draco_mesh_compression) are not supported"),
            std::string::npos)
      << result.output;
  EXPECT_EQ(result.output.find("bufferView"), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(CliModel, BoundsAndTrianglesPrintedAndRecorded) {
  const TempDirectory dir("penumbra_cli_bounds");
  const fs::path out = dir.path() / "out";
  const auto result = runPenumbra("export --scene plate --width 32 --height 24 --set "
                                  "light.resolution=128 --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  // plate: a 12 x 12 ground and a unit plate at y = 1, 4 triangles.
  EXPECT_NE(result.output.find("scene 'plate': 4 triangles, 2 objects; bounds x [-6, 6] y [0, 1] "
                               "z [-6, 6] (size 12 x 1 x 12)"),
            std::string::npos)
      << result.output;
  std::ifstream in(out / "run.json");
  const auto run = nlohmann::json::parse(in);
  EXPECT_EQ(run["triangles"], 4);
  EXPECT_EQ(run["bounds"]["min"], nlohmann::json({-6.0, 0.0, -6.0}));
  EXPECT_EQ(run["bounds"]["max"], nlohmann::json({6.0, 1.0, 6.0}));
}

// The window's trace panel shows traceCommandLine() for the picked pixel at the view's eye
// size; run as printed, the CLI records that pixel of an image of that size.
TEST(CliTrace, CommandLineRecordsTheImageSizeAndThePixel) {
  const TempDirectory dir("penumbra_cli_trace");
  const fs::path out = dir.path() / "t.json";
  const std::string command =
      traceCommandLine("cube", 30, 40, 61, 67, {"light.resolution=128", "trace.rays=2"});
  ASSERT_EQ(command.rfind("penumbra trace ", 0), 0u) << command;
  EXPECT_NE(command.find("--width 61 --height 67"), std::string::npos) << command;
  const auto result = runPenumbra(command.substr(std::string("penumbra ").size()) + " --out " +
                                  out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  std::ifstream in(out);
  const auto trace = nlohmann::json::parse(in);
  EXPECT_EQ(trace["image_size"], nlohmann::json({61, 67}));
  EXPECT_EQ(trace["pixel"], nlohmann::json({30, 40}));
  EXPECT_EQ(trace["rays"], 4);
  // A pixel outside that image is refused, naming the size.
  const auto outside = runPenumbra("trace --scene cube --pixel 61,10 --width 61 --height 67");
  EXPECT_EQ(outside.exitCode, 2) << outside.output;
  EXPECT_NE(outside.output.find("inside the 61x67 image"), std::string::npos) << outside.output;
}

TEST(CliTrace, ScenePathsAreQuotedForTheShell) {
  EXPECT_NE(traceCommandLine("/my models/a'b.glb", 0, 0, 8, 8, {}).find("'/my models/a'\\''b.glb'"),
            std::string::npos)
      << traceCommandLine("/my models/a'b.glb", 0, 0, 8, 8, {});
}

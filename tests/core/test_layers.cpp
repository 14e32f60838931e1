// Layers that point one way (docs/design.md#layers,
// docs/decisions/044-layers-point-one-way.md): every `#include "..."` in app/ and stages/ is
// resolved the way the compiler does (the including file's folder, then app/, stages/,
// shaders/) and the file it names must sit in the includer's own layer folder or in a lower
// layer. Folders on one rank are peers and may not include each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// The layer order, lowest first. A path belongs to the longest prefix listed; a folder may
// include its own folder and anything of a strictly lower rank.
struct Layer {
  const char* prefix;
  int rank;
};
const std::vector<Layer> kLayers = {
    {"shaders/shared/", 0},     // layout headers shared by GLSL and C++
    {"app/base/", 1},           // input errors, the JSON reader
    {"app/scene/", 2},          // plain scene data and its loaders
    {"app/gl/", 3},             // GL wrappers, the scene on the GPU, layout checks
    {"app/core/", 4},           // Stage, Param, Frame, Pipeline
    {"app/io/", 5},             // images, colour maps, output paths, the headless session
    {"app/reference/", 6},      // the Embree reference and error metrics
    {"app/stats/", 6},          // the hash statistics
    {"app/figures/", 6},        // cairo figure pieces
    {"stages/", 7},             // every stage (its subfolders are one layer)
    {"app/bench/", 8},          // speed against error
    {"app/export/", 8},         // export of a frame, the trace's steps as JSON
    {"app/cli/", 9},            // the headless commands
    {"app/window/", 9},         // the ImGui window
    {"app/cli/main.cpp", 10},   // the program: links the commands and the window
};

const Layer* layerOf(const std::string& path) {
  const Layer* best = nullptr;
  for (const Layer& layer : kLayers)
    if (path.rfind(layer.prefix, 0) == 0 &&
        (!best || std::string(layer.prefix).size() > std::string(best->prefix).size()))
      best = &layer;
  return best;
}

// The folder that counts as "its own" for a path: the layer prefix (stages/ as a whole).
bool allowed(const std::string& from, const std::string& to) {
  const Layer* a = layerOf(from);
  const Layer* b = layerOf(to);
  if (!a || !b) return true;  // outside the layered tree (third-party, generated)
  if (std::string(b->prefix) == a->prefix) return true;
  // main.cpp is a file inside app/cli/: it may include its folder too.
  if (std::string(a->prefix) == "app/cli/main.cpp" && std::string(b->prefix) == "app/cli/")
    return true;
  return b->rank < a->rank;
}

struct Include {
  std::string from, to;  // repository-relative paths
  int line;
};

// The repository path `name` resolves to from `from`, or "" (a system or third-party header).
std::string resolve(const fs::path& root, const std::string& from, const std::string& name) {
  const fs::path local = fs::path(from).parent_path() / name;
  if (fs::exists(root / local)) return local.lexically_normal().generic_string();
  for (const char* dir : {"app", "stages", "shaders"})
    if (fs::exists(root / dir / name)) return (fs::path(dir) / name).lexically_normal().generic_string();
  return "";
}

// Calls found(line, name) for every `#include "name"` of one file (C++ or GLSL).
template <class Found>
void forEachInclude(const fs::path& file, const Found& found) {
  static const std::regex directive(R"re(^\s*#\s*include\s*"([^"]+)")re");
  std::ifstream in(file);
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    std::smatch match;
    if (std::regex_search(text, match, directive)) found(line, match[1].str());
  }
}

std::vector<Include> includesIn(const fs::path& root) {
  std::vector<Include> all;
  for (const char* top : {"app", "stages"})
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      const std::string ext = entry.path().extension().string();
      if (!entry.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
      const std::string from = fs::relative(entry.path(), root).generic_string();
      forEachInclude(entry.path(), [&](int line, const std::string& name) {
        const std::string to = resolve(root, from, name);
        if (!to.empty()) all.push_back({from, to, line});
      });
    }
  return all;
}

TEST(Layers, NoIncludeRunsUpALayer) {
  const fs::path root = PENUMBRA_SOURCE_DIR;
  const std::vector<Include> includes = includesIn(root);
  ASSERT_GT(includes.size(), 500u) << "the scan found too few includes to be reading the tree";
  std::ostringstream upward;
  int count = 0;
  for (const Include& include : includes)
    if (!allowed(include.from, include.to)) {
      ++count;
      upward << "  " << include.from << ":" << include.line << " includes " << include.to << "\n";
    }
  EXPECT_EQ(count, 0) << "includes that run up a layer (or across peers; the order is in "
                         "tests/core/test_layers.cpp and docs/design.md#layers):\n"
                      << upward.str();
}

TEST(Layers, EveryScannedFileHasALayer) {
  const fs::path root = PENUMBRA_SOURCE_DIR;
  for (const char* top : {"app", "stages"})
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      const std::string ext = entry.path().extension().string();
      if (!entry.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
      const std::string path = fs::relative(entry.path(), root).generic_string();
      EXPECT_NE(layerOf(path), nullptr) << path << " is in no layer: add its folder to kLayers";
    }
}

// The rule itself: it refuses what it must (so a clean tree is a finding, not a blind check).
TEST(Layers, TheRuleRefusesUpwardAndPeerIncludes) {
  EXPECT_FALSE(allowed("app/core/frame.h", "stages/shared_inputs/light/auto_settings.h"));
  EXPECT_FALSE(allowed("app/scene/scene.cpp", "app/core/frame.h"));
  EXPECT_FALSE(allowed("app/window/panels/ui_export.cpp", "app/cli/export_command.h"));
  EXPECT_FALSE(allowed("app/cli/trace_command.cpp", "app/window/window_app.h"));
  EXPECT_FALSE(allowed("app/stats/hash_stats.cpp", "app/reference/reference_trace.h"));
  EXPECT_TRUE(allowed("app/cli/main.cpp", "app/window/window_app.h"));
  EXPECT_TRUE(allowed("app/cli/main.cpp", "app/cli/export_command.h"));
  EXPECT_TRUE(allowed("stages/monte_carlo/trace/trace.cpp", "stages/shared_inputs/light/light_input.h"));
  EXPECT_TRUE(allowed("app/gl/gpu_scene.h", "app/scene/scene.h"));
  EXPECT_TRUE(allowed("app/gl/gpu_layout.h", "shaders/shared/light_block.h"));
  // A stage's layout header sits in its stage folder: a layer below the stages may not read it.
  EXPECT_FALSE(allowed("app/gl/gpu_layout.h", "stages/monte_carlo/classify/classify_layout.h"));
  EXPECT_TRUE(allowed("stages/monte_carlo/trace/trace.cpp",
                      "stages/monte_carlo/classify/classify_layout.h"));
}

// The GLSL side of the same order: a shared library or header in shaders/shared/ includes only
// shaders/shared/ (a stage's layout header, in its stage folder, is read by that stage's
// shaders and its peers', never by the shared code every stage includes). Resolved the way
// app/gl/shader_program.cpp does: the including file's folder, then shaders/, then the source root.
TEST(Layers, SharedShadersIncludeOnlySharedFiles) {
  const fs::path root = PENUMBRA_SOURCE_DIR;
  int includes = 0;
  for (const auto& entry : fs::directory_iterator(root / "shaders/shared")) {
    if (!entry.is_regular_file()) continue;
    const std::string from = fs::relative(entry.path(), root).generic_string();
    forEachInclude(entry.path(), [&](int line, const std::string& name) {
      std::string to;
      for (const fs::path& base : {fs::path(from).parent_path(), fs::path("shaders"), fs::path()})
        if (fs::is_regular_file(root / base / name)) {
          to = (base / name).lexically_normal().generic_string();
          break;
        }
      ++includes;
      EXPECT_EQ(to.rfind("shaders/shared/", 0), 0u)
          << from << ":" << line << " includes \"" << name << "\" (" << (to.empty() ? "not found" : to)
          << "): shared shaders include only shaders/shared/";
    });
  }
  EXPECT_GE(includes, 15) << "the scan found too few includes to be reading shaders/shared/";
}

}  // namespace

#include "window_test.h"

#include <fstream>

std::filesystem::path scratchDirectory(const std::string& name) {
  const auto directory = std::filesystem::temp_directory_path() / ("penumbra_" + name);
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  return directory;
}

std::filesystem::path writeScript(const std::filesystem::path& directory, const std::string& json) {
  const auto path = directory / "script.json";
  std::ofstream(path) << json;
  return path;
}

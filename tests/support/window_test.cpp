#include "window_test.h"

#include <fstream>

std::filesystem::path writeScript(const std::filesystem::path& directory, const std::string& json) {
  const auto path = directory / "script.json";
  std::ofstream(path) << json;
  return path;
}

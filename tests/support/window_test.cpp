#include "window_test.h"

#include <algorithm>
#include <fstream>

#include "io/image_export.h"

std::filesystem::path writeScript(const std::filesystem::path& directory, const std::string& json) {
  const auto path = directory / "script.json";
  std::ofstream(path) << json;
  return path;
}

::testing::AssertionResult playLesson(const std::string& lessonFile, int steps,
                                      const std::vector<std::string>& figures,
                                      const std::filesystem::path& exportDir,
                                      CommandResult* result) {
  const CommandResult run = runPenumbra("lesson " + lessonFile + " --export " + exportDir.string());
  if (result) *result = run;
  if (run.exitCode != 0)
    return ::testing::AssertionFailure() << lessonFile << " exited " << run.exitCode << ":\n" << run.output;
  const std::string last = "lesson step " + std::to_string(steps) + "/" + std::to_string(steps);
  if (run.output.find(last) == std::string::npos)
    return ::testing::AssertionFailure() << "no \"" << last << "\" in:\n" << run.output;
  for (const std::string& name : figures)
    if (!std::filesystem::exists(exportDir / name))
      return ::testing::AssertionFailure() << lessonFile << " exported no " << name << ":\n" << run.output;
  return ::testing::AssertionSuccess();
}

bool penumbraPixel(const std::filesystem::path& directory, int& x, int& y) {
  if (runPenumbra("export --width 160 --height 120 --out " + (directory / "cli").string()).exitCode != 0)
    return false;
  int w = 0, h = 0;
  std::vector<std::string> channels;
  const auto mask = readExr(directory / "cli" / "classify.mask.exr", w, h, channels);
  const auto cost = readExr(directory / "cli" / "trace.cost.exr", w, h, channels);
  const auto earlyOuts = std::find(channels.begin(), channels.end(), "earlyOuts");  // EXR sorts them
  if (earlyOuts == channels.end() || cost.size() != mask.size() * channels.size()) return false;
  const size_t channel = size_t(earlyOuts - channels.begin());
  for (int i = int(mask.size()) / 2; i < int(mask.size()); ++i)
    if (mask[size_t(i)] == 2.0f && cost[size_t(i) * channels.size() + channel] == 0.0f) {
      x = i % w;
      y = h - 1 - i / w;
      return true;
    }
  return false;
}

#include "bench/bench_session.h"

#include <cstdio>
#include <exception>
#include <vector>

#include "scene/scene_builtin.h"

int openBenchSession(const std::string& command, const std::string& sceneName, BenchSession& session) {
  std::string error;
  session.context = GlContext::createHeadless(error);
  if (!session.context) {
    std::fprintf(stderr, "penumbra %s: %s\n", command.c_str(), error.c_str());
    return 1;
  }
  std::vector<std::string> warnings;
  try {
    session.scene = loadScene(sceneName, warnings);
  } catch (const std::exception& failure) {
    std::fprintf(stderr, "penumbra %s: %s\n", command.c_str(), failure.what());
    return 2;
  }
  session.gpuScene = std::make_unique<GpuScene>(session.scene);
  return 0;
}

#include "cli/hash_command.h"

#include <bit>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <vector>

#include "gl/gl_context.h"
#include "gl/hash_batch.h"

// The words go out as they lie in memory: little-endian on every host we build for.
static_assert(std::endian::native == std::endian::little, "penumbra hash writes host order");

std::string checkHashOptions(const HashOptions& options) {
  if (!hashKindFromName(options.hash))
    return "unknown hash '" + options.hash + "'; valid: " + hashKindList();
  if (options.count < 1 || options.count > 0xFFFFFFFFull)
    return "--count must be in [1, 4294967295] (the seeds 1..N are 32-bit words), got " +
           std::to_string(options.count);
  return "";
}

int writeHashStream(const HashOptions& options, std::FILE* out) {
  const HashKind kind = *hashKindFromName(options.hash);
  GpuHashBatch batch;
  std::vector<glm::uvec4> hashes(GpuHashBatch::kMaxPerDispatch);
  for (std::uint64_t done = 0; done < options.count;) {
    const auto chunk =
        std::uint32_t(std::min<std::uint64_t>(GpuHashBatch::kMaxPerDispatch, options.count - done));
    batch.hashLinear(std::uint32_t(done + 1), chunk, options.key, kind, hashes.data());
    if (std::fwrite(hashes.data(), sizeof(glm::uvec4), chunk, out) != chunk ||
        std::fflush(out) != 0) {
      if (errno == EPIPE) return 0;  // the reader has all it wanted
      std::fprintf(stderr, "penumbra hash: write failed: %s\n", std::strerror(errno));
      return 1;
    }
    done += chunk;
  }
  return 0;
}

int runHashCommand(const HashOptions& options) {
  if (const std::string problem = checkHashOptions(options); !problem.empty()) {
    std::fprintf(stderr, "penumbra hash: %s\n", problem.c_str());
    return 2;
  }
  std::string error;
  auto context = GlContext::createHeadless(error);
  if (!context) {
    std::fprintf(stderr, "penumbra hash: %s\n", error.c_str());
    return 1;
  }
  std::signal(SIGPIPE, SIG_IGN);  // a closed pipe becomes EPIPE, handled as the end
  try {
    return writeHashStream(options, stdout);
  } catch (const std::exception& problem) {
    std::fprintf(stderr, "penumbra hash: %s\n", problem.what());
    return 1;
  }
}

// `penumbra hash --hash NAME --count N [--key K]`: the raw output of one hash function of
// the pipeline (thesis §3.1, Appendix A) for external test batteries, e.g.
//     penumbra hash --hash md5_16 --count 100000000 | dieharder -g 200 -a
// Inputs are the linear sequence the thesis tested with: seed_i = (i, 0, 0, 0) for
// i = 1, 2, ..., N; output: all four 32-bit words of each hash, in order, little-endian.
// Computed on the GPU (headless context), 2^20 hashes per dispatch.
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>

struct HashOptions {
  std::string hash = "md5_16";       // md5_16, md5_64 or pcg3d
  std::uint64_t count = 1u << 20;    // number of hashes N: 1 .. 2^32 - 1 (16 bytes each)
  std::uint32_t key = 0;             // the Appendix A key, XORed into the seed
};

// "" when the options are valid, else what is wrong (naming the valid hash names).
std::string checkHashOptions(const HashOptions& options);

// Validates (exit 2 with a message), opens a headless context (exit 1 if it cannot),
// streams to stdout. A closed pipe (the battery has read enough) ends it with status 0.
int runHashCommand(const HashOptions& options);

// The stream itself, for valid options and a current GL context: returns 0, or 1 after a
// write error other than a closed pipe (reported on stderr).
int writeHashStream(const HashOptions& options, std::FILE* out);

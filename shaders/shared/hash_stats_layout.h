// The `hash_stats` stage's GPU passes (shaders/hash/hash_stats/hash_stats_*.comp; thesis §3.1,
// §4.3, Appendix A): numbers shared by C++ (app/stats/hash_stats_gpu.cpp, with
// static_asserts) and GLSL. The GPU generates the hash outputs and reduces them to integer
// counts and per-invocation float partial sums; the CPU adds the partials in double and
// computes every statistic (app/stats/hash_stats.cpp).
//
// One *sample* i of a pattern is four words: the hash of input i (words x and y: the light
// sample (u, v) the trace would draw), the x word of its right-hand pixel's hash (seed.x + 1)
// and the x word of the same input under the next frame key (key + 1).
#define HASH_STATS_GROUP_SIZE 64
#define HASH_STATS_PER_INVOCATION 64  // consecutive samples one accumulate invocation reads
#define HASH_STATS_CHUNK 1000000      // samples per generate/accumulate pass (1600 FIPS blocks)

#define HASH_STATS_BUCKETS 1024       // 1D uniformity: the top 10 bits of word x
#define HASH_STATS_BUCKET_SHIFT 22u
#define HASH_STATS_PAIR_SIDE 64       // 2D pairs: the top 6 bits of words x and y
#define HASH_STATS_PAIR_SHIFT 26u
// uint counts[]: 1D buckets, then the 64 x 64 pair cells (row = y bucket), then ones per bit.
#define HASH_STATS_COUNT_PAIRS HASH_STATS_BUCKETS
#define HASH_STATS_COUNT_BITS (HASH_STATS_BUCKETS + HASH_STATS_PAIR_SIDE * HASH_STATS_PAIR_SIDE)
#define HASH_STATS_COUNT_TOTAL (HASH_STATS_COUNT_BITS + 32)

// float sums[invocation * HASH_STATS_SUM_STRIDE + k]: each invocation's means and centred
// (co)moments of c = (x >> 8) / 2^24 - 1/2 of word x, r and f the same of the right-hand and
// next-frame words, and (a, b) = (c, c of the next sample in the chunk). Means are stored as
// an offset from the invocation's first sample (REF_*, exact in float), and moments are
// centred (two passes over the 64 samples), so that nearly constant streams keep their
// variance; the CPU joins the invocations in double (Chan, Golub & LeVeque 1979).
#define HASH_STATS_SUM_STRIDE 20
#define HASH_STATS_SUM_N 0        // samples
#define HASH_STATS_SUM_MEAN_C 1   // mean of c minus REF_C (every MEAN_* likewise)
#define HASH_STATS_SUM_M2_C 2     // sum (c - mean c)^2
#define HASH_STATS_SUM_MEAN_R 3
#define HASH_STATS_SUM_M2_R 4
#define HASH_STATS_SUM_CO_CR 5    // sum (c - mean c)(r - mean r)
#define HASH_STATS_SUM_MEAN_F 6
#define HASH_STATS_SUM_M2_F 7
#define HASH_STATS_SUM_CO_CF 8
#define HASH_STATS_SUM_NEXT_N 9   // pairs (a, b) of consecutive samples
#define HASH_STATS_SUM_MEAN_A 10
#define HASH_STATS_SUM_M2_A 11
#define HASH_STATS_SUM_MEAN_B 12
#define HASH_STATS_SUM_M2_B 13
#define HASH_STATS_SUM_CO_AB 14
#define HASH_STATS_SUM_REF_C 15   // c of the invocation's first sample (also for a and b)
#define HASH_STATS_SUM_REF_R 16
#define HASH_STATS_SUM_REF_F 17
#define HASH_STATS_SUM_COUNT 18

// FIPS 140-2 (4.9.1) on 20,000-bit blocks of consecutive x words, bits LSB first:
// uint blocks[block * HASH_STATS_FIPS_STRIDE + k].
#define HASH_STATS_FIPS_WORDS 625
#define HASH_STATS_FIPS_STRIDE 32
#define HASH_STATS_FIPS_ONES 0       // ones in the block
#define HASH_STATS_FIPS_POKER 1      // 16 counts of the 5,000 4-bit nibbles
#define HASH_STATS_FIPS_RUNS 17      // runs of 0s of length 1..5, 6+, then runs of 1s
#define HASH_STATS_FIPS_LONGEST 29   // longest run
#define HASH_STATS_FIPS_TOTAL_RUNS 30

// Avalanche: for the first HASH_STATS_AVALANCHE_INPUTS inputs whose seed.x has bit i clear,
// set bit i and count how often bit j of word x flips: uint flips[i * 32 + j]; the number of
// such inputs in flips[HASH_STATS_FLIPS_INPUTS + i]. (Taking only inputs with the bit clear
// keeps every pair of inputs once: with the linear pattern, flipping bit 0 of 1 and of 2
// would otherwise compare the same two inputs twice and double the variance.)
#define HASH_STATS_AVALANCHE_INPUTS 65536u
#define HASH_STATS_FLIPS_INPUTS 1024
#define HASH_STATS_FLIPS_TOTAL (HASH_STATS_FLIPS_INPUTS + 32)

// Input patterns (shaders/hash/hash_stats/hash_patterns.glsl).
#define HASH_PATTERN_LINEAR 0  // seed (i + 1, 0, 0, 0): the thesis's 1, 2, ..., n (§3.1)
#define HASH_PATTERN_PIXELS 1  // the renderer's seeds (x, y, ray, 0) of a 1024 x 1024 image
#define HASH_PATTERN_MORTON 2  // pixels (x, y, 0, 0) in Morton (Z) order
#define HASH_PATTERN_FRAMES 3  // pixel 0, consecutive frame keys key * 2^24 + i
#define HASH_PATTERN_COUNT 4

// Reference "hashes" for the known-answer tests, only in the hash_stats shaders.
#define HASH_STATS_IDENTITY 100  // returns the seed itself
#define HASH_STATS_CONSTANT 101  // returns a constant

// Uniform locations (each pass uses those it needs).
#define HASH_STATS_LOC_COUNT 0    // samples (or FIPS blocks, or avalanche inputs) this dispatch
#define HASH_STATS_LOC_FIRST 1    // input number of the chunk's first sample
#define HASH_STATS_LOC_KEY 2
#define HASH_STATS_LOC_KIND 3     // HASH_* or HASH_STATS_IDENTITY / HASH_STATS_CONSTANT
#define HASH_STATS_LOC_PATTERN 4  // HASH_PATTERN_*

// Storage buffer bindings.
#define HASH_STATS_SAMPLES_BINDING 0    // uvec4 samples[] (x, y, right x, next-frame x)
#define HASH_STATS_COUNTS_BINDING 1     // uint counts[HASH_STATS_COUNT_TOTAL]
#define HASH_STATS_SUMS_BINDING 2       // float sums[]
#define HASH_STATS_FIPS_BINDING 3       // uint blocks[]
#define HASH_STATS_AVALANCHE_BINDING 4  // uint flips[HASH_STATS_FLIPS_TOTAL]

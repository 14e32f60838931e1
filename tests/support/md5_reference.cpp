#include "md5_reference.h"

#include <bit>
#include <cmath>
#include <cstdio>
#include <vector>

#include "shared/hash_kinds.h"

namespace md5ref {
namespace {

std::uint32_t rotl(std::uint32_t x, int s) { return (x << s) | (x >> (32 - s)); }

// RFC 1321 §3.4: T[i] = floor(4294967296 * |sin(i)|), i = 1..64, computed, not typed in.
const std::array<std::uint32_t, 65>& sineTable() {
  static const std::array<std::uint32_t, 65> table = [] {
    std::array<std::uint32_t, 65> t{};
    for (int i = 1; i <= 64; ++i)
      t[i] = std::uint32_t(std::floor(4294967296.0 * std::fabs(std::sin(double(i)))));
    return t;
  }();
  return table;
}

std::uint32_t F(std::uint32_t x, std::uint32_t y, std::uint32_t z) { return (x & y) | (~x & z); }
std::uint32_t G(std::uint32_t x, std::uint32_t y, std::uint32_t z) { return (x & z) | (y & ~z); }
std::uint32_t H(std::uint32_t x, std::uint32_t y, std::uint32_t z) { return x ^ y ^ z; }
std::uint32_t I(std::uint32_t x, std::uint32_t y, std::uint32_t z) { return y ^ (x | ~z); }

// RFC 1321 §3.4, the four rounds written out as the RFC prints them:
// "[abcd k s i] denote the operation a = b + ((a + F(b,c,d) + X[k] + T[i]) <<< s)".
void processBlock(std::uint32_t state[4], const std::uint8_t* block) {
  std::uint32_t X[16];
  for (int j = 0; j < 16; ++j)
    X[j] = std::uint32_t(block[4 * j]) | std::uint32_t(block[4 * j + 1]) << 8 |
           std::uint32_t(block[4 * j + 2]) << 16 | std::uint32_t(block[4 * j + 3]) << 24;
  const auto& T = sineTable();
  std::uint32_t a = state[0], b = state[1], c = state[2], d = state[3];
  auto step = [&](auto fn, std::uint32_t& p, std::uint32_t q, std::uint32_t r, std::uint32_t s,
                  int k, int shift, int i) { p = q + rotl(p + fn(q, r, s) + X[k] + T[i], shift); };
  // Per round: (k, s, i) of each step, as listed in the RFC.
  const int r1[16][3] = {{0, 7, 1},   {1, 12, 2},  {2, 17, 3},  {3, 22, 4},
                         {4, 7, 5},   {5, 12, 6},  {6, 17, 7},  {7, 22, 8},
                         {8, 7, 9},   {9, 12, 10}, {10, 17, 11}, {11, 22, 12},
                         {12, 7, 13}, {13, 12, 14}, {14, 17, 15}, {15, 22, 16}};
  const int r2[16][3] = {{1, 5, 17},  {6, 9, 18},  {11, 14, 19}, {0, 20, 20},
                         {5, 5, 21},  {10, 9, 22}, {15, 14, 23}, {4, 20, 24},
                         {9, 5, 25},  {14, 9, 26}, {3, 14, 27},  {8, 20, 28},
                         {13, 5, 29}, {2, 9, 30},  {7, 14, 31},  {12, 20, 32}};
  const int r3[16][3] = {{5, 4, 33},  {8, 11, 34}, {11, 16, 35}, {14, 23, 36},
                         {1, 4, 37},  {4, 11, 38}, {7, 16, 39},  {10, 23, 40},
                         {13, 4, 41}, {0, 11, 42}, {3, 16, 43},  {6, 23, 44},
                         {9, 4, 45},  {12, 11, 46}, {15, 16, 47}, {2, 23, 48}};
  const int r4[16][3] = {{0, 6, 49},  {7, 10, 50}, {14, 15, 51}, {5, 21, 52},
                         {12, 6, 53}, {3, 10, 54}, {10, 15, 55}, {1, 21, 56},
                         {8, 6, 57},  {15, 10, 58}, {6, 15, 59}, {13, 21, 60},
                         {4, 6, 61},  {11, 10, 62}, {2, 15, 63}, {9, 21, 64}};
  // The RFC's operand order cycles [abcd], [dabc], [cdab], [bcda].
  auto round = [&](auto fn, const int (*ops)[3]) {
    for (int j = 0; j < 16; j += 4) {
      step(fn, a, b, c, d, ops[j][0], ops[j][1], ops[j][2]);
      step(fn, d, a, b, c, ops[j + 1][0], ops[j + 1][1], ops[j + 1][2]);
      step(fn, c, d, a, b, ops[j + 2][0], ops[j + 2][1], ops[j + 2][2]);
      step(fn, b, c, d, a, ops[j + 3][0], ops[j + 3][1], ops[j + 3][2]);
    }
  };
  round(F, r1);
  round(G, r2);
  round(H, r3);
  round(I, r4);
  state[0] += a;
  state[1] += b;
  state[2] += c;
  state[3] += d;
}

}  // namespace

Digest md5(const void* data, size_t size) {
  // §3.1-3.2: append 0x80, zeros to 56 mod 64, then the bit length as 64 bits little-endian.
  std::vector<std::uint8_t> message(static_cast<const std::uint8_t*>(data),
                                    static_cast<const std::uint8_t*>(data) + size);
  message.push_back(0x80);
  while (message.size() % 64 != 56) message.push_back(0);
  const std::uint64_t bits = std::uint64_t(size) * 8;
  for (int j = 0; j < 8; ++j) message.push_back(std::uint8_t(bits >> (8 * j)));
  // §3.3: A = 01 23 45 67, B = 89 ab cd ef, C = fe dc ba 98, D = 76 54 32 10 (low byte first).
  std::uint32_t state[4] = {0x67452301u, 0xefcdab89u, 0x98badcfeu, 0x10325476u};
  for (size_t offset = 0; offset < message.size(); offset += 64)
    processBlock(state, &message[offset]);
  Digest digest;
  for (int w = 0; w < 4; ++w)
    for (int j = 0; j < 4; ++j) digest[4 * w + j] = std::uint8_t(state[w] >> (8 * j));
  return digest;
}

std::string toHex(const Digest& digest) {
  std::string hex;
  char byte[3];
  for (std::uint8_t b : digest) {
    std::snprintf(byte, sizeof byte, "%02x", b);
    hex += byte;
  }
  return hex;
}

glm::uvec4 md5Rand64(glm::uvec4 seed, std::uint32_t key) {
  std::uint8_t bytes[16];
  for (int w = 0; w < 4; ++w)
    for (int j = 0; j < 4; ++j) bytes[4 * w + j] = std::uint8_t((seed[w] ^ key) >> (8 * j));
  const Digest digest = md5(bytes, sizeof bytes);
  glm::uvec4 words;
  for (int w = 0; w < 4; ++w)
    words[w] = std::uint32_t(digest[4 * w]) | std::uint32_t(digest[4 * w + 1]) << 8 |
               std::uint32_t(digest[4 * w + 2]) << 16 | std::uint32_t(digest[4 * w + 3]) << 24;
  return words;
}

glm::uvec4 md5Rand16(glm::uvec4 seed, std::uint32_t key) { return md5RandSteps(seed, key, 16); }

glm::uvec4 md5RandSteps(glm::uvec4 seed, std::uint32_t key, int stepCount) {
  // The 16 steps of the thesis listing, as data: round function (0: (x&y)|(~x&z),
  // 1: (z&x)|(~z&y), 2: x^y^z, 3: y^(x|~z), of t = tD), message word (-1: a word the
  // listing comments out, i.e. zero), constant as printed, rotation.
  struct Step { int function, word; std::uint32_t constant; int shift; };
  static const Step steps[16] = {
      {0, 0, 0xD76AA478u, 7},   {0, 1, 0xE8C7B757u, 12},  {0, 2, 0x242070DBu, 17},
      {0, 3, 0xC1BDCEEFu, 22},  {1, 1, 0xF61E2562u, 5},   {1, -1, 0xC040B341u, 9},
      {1, -1, 0x265E5A52u, 14}, {1, 0, 0xE9B6C7ABu, 20},  {2, -1, 0xFFFA3942u, 4},
      {2, -1, 0x8771F681u, 11}, {2, -1, 0x6D9D6122u, 16}, {2, -1, 0xFDE5380Cu, 23},
      {3, 0, 0xF4292244u, 6},   {3, -1, 0x432AFF98u, 10}, {3, -1, 0xAB9423A7u, 15},
      {3, -1, 0xFC93A039u, 21}};
  const std::uint32_t message[4] = {seed.x ^ key, seed.y ^ key, seed.z ^ key, seed.w ^ key};
  std::uint32_t digest[4] = {0x01234567u, 0x89ABCDEFu, 0xFEDCBA98u, 0x76543210u};
  std::uint32_t t[4] = {digest[0], digest[1], digest[2], digest[3]};
  for (int s = 0; s < stepCount; ++s) {
    const Step& step = steps[s];
    const std::uint32_t x = t[0], y = t[1], z = t[2];
    const std::uint32_t f = step.function == 0   ? (x & y) | (~x & z)
                            : step.function == 1 ? (z & x) | (~z & y)
                            : step.function == 2 ? x ^ y ^ z
                                                 : y ^ (x | ~z);
    const std::uint32_t sum = t[0] + f + (step.word < 0 ? 0u : message[step.word]) + step.constant;
    t[0] = t[1] + rotl(sum, step.shift);
    // tD = tD.yzwx; digest += tD;
    const std::uint32_t rotated[4] = {t[1], t[2], t[3], t[0]};
    for (int w = 0; w < 4; ++w) {
      t[w] = rotated[w];
      digest[w] += t[w];
    }
  }
  return {digest[0], digest[1], digest[2], digest[3]};
}

glm::uvec3 pcg3d(glm::uvec3 v) {
  // Jarzynski & Olano 2020, listing of pcg3d (unsigned arithmetic modulo 2^32).
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  return v;
}

glm::uvec4 pcg3dRand(glm::uvec4 seed, std::uint32_t key) {
  const glm::uvec3 h = pcg3d({seed.x ^ (seed.w * 0x9E3779B9u), seed.y, seed.z ^ key});
  return {h, pcg3d(h).x};
}

// ISO C (C99 §7.20.2.2) gives this portable rand() as its example; srand(seed) sets `next`.
struct IsoCRand {
  std::uint32_t next;
  int operator()() {
    next = next * 1103515245u + 12345u;
    return int((next / 65536u) % 32768u);
  }
};

static std::uint32_t pixelIndex(glm::uvec4 seed, std::uint32_t key) {
  // x + 4096 y + 2^24 ray + 2^28 w, modulo 2^32, XOR key.
  return (seed.x + 4096u * seed.y + 16777216u * seed.z + 268435456u * seed.w) ^ key;
}

glm::uvec4 lcg15Rand(glm::uvec4 seed, std::uint32_t key) {
  IsoCRand rand{pixelIndex(seed, key)};
  glm::uvec4 words;
  for (int i = 0; i < 4; ++i) words[i] = std::uint32_t(rand()) * 131072u;  // rand() * 2^17
  return words;
}

glm::uvec4 lcg32Rand(glm::uvec4 seed, std::uint32_t key) {
  // Numerical Recipes' "quick and dirty" generator: I(j+1) = 1664525 I(j) + 1013904223.
  std::uint64_t state = pixelIndex(seed, key);
  glm::uvec4 words;
  for (int i = 0; i < 4; ++i) words[i] = std::uint32_t(state = (1664525u * state + 1013904223u) % 4294967296u);
  return words;
}

std::uint32_t xxhash32(glm::uvec4 p) {
  // Collet's XXH32 primes; the 4-word form of Jarzynski & Olano 2020.
  constexpr std::uint32_t prime2 = 0x85EBCA77u, prime3 = 0xC2B2AE3Du, prime4 = 0x27D4EB2Fu,
                          prime5 = 0x165667B1u;
  std::uint32_t h = p.w + prime5 + p.x * prime3;
  h = std::rotl(h, 17) * prime4;
  h = std::rotl(h + p.y * prime3, 17) * prime4;
  h = std::rotl(h + p.z * prime3, 17) * prime4;
  h = (h ^ (h >> 15)) * prime2;
  h = (h ^ (h >> 13)) * prime3;
  return h ^ (h >> 16);
}

glm::uvec4 xxhash32Rand(glm::uvec4 seed, std::uint32_t key) {
  glm::uvec4 words;
  for (std::uint32_t i = 0; i < 4; ++i)
    words[i] = xxhash32({seed.x ^ key, seed.y ^ key, seed.z ^ key, (seed.w ^ key) * 4u + i});
  return words;
}

glm::uvec4 hashRand(glm::uvec4 seed, std::uint32_t key, int kind) {
  switch (kind) {
    case HASH_MD5_16: return md5Rand16(seed, key);
    case HASH_MD5_64: return md5Rand64(seed, key);
    case HASH_PCG3D: return pcg3dRand(seed, key);
    case HASH_MD5_4: return md5RandSteps(seed, key, 4);
    case HASH_MD5_8: return md5RandSteps(seed, key, 8);
    case HASH_LCG15: return lcg15Rand(seed, key);
    case HASH_LCG32: return lcg32Rand(seed, key);
    case HASH_XXHASH32: return xxhash32Rand(seed, key);
  }
  return {};
}

glm::vec2 toUnitSquare(glm::uvec2 bits) {
  return {float(double(bits.x >> 8) / 16777216.0), float(double(bits.y >> 8) / 16777216.0)};
}

}  // namespace md5ref

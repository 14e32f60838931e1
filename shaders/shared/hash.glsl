// Random numbers without state (thesis §3.1, after Tzeng & Wei 2008): each pixel hashes its
// own coordinates, so every ray's light sample is computed independently and in parallel.
// The thesis uses a reduced 16-round MD5 (Appendix A); §4.3 reports it costs < 10% of the
// frame. For comparison we also provide the full 64-round MD5 and pcg3d (Jarzynski & Olano
// 2020, "Hash Functions for GPU Rendering"), the listing cut to 4 and 8 steps, two LCGs and
// xxhash32, selected by hashRand(seed, key, hashKind).
//
// Convention for the pipeline: seed = (pixel.x, pixel.y, 0, 0) ("screen coordinates are
// used for the seed", Appendix A), key = frame.keys.x; the first light sample is
// toUnitSquare(h.xy), a second one toUnitSquare(h.zw).
//
// C++ twins (written independently, not copied) in tests/support/md5_reference.cpp check
// this file bit for bit on 10^6 inputs per hash (tests/stages/test_hash.cpp).
#include "hash_kinds.h"

// Thesis Appendix A, line for line. Differences from the printed listing, none of which
// changes a bit of the result:
//  - `unsigned int` is spelled `uint` (GLSL 4.50 reserves `unsigned`);
//  - the message words the listing comments out (d04..d15: padding and zeros, "values
//    commented out as they do not actually affect the calculation") are left out; none of
//    d04 or d15 is read by the 16 rounds, and the others are zero.
// Followed literally, including what differs from RFC 1321 MD5: the digest starts at
// 0x01234567, 0x89ABCDEF, 0xFEDCBA98, 0x76543210 (bytes of the RFC init read big-endian);
// the round function reads tD.x (the word being replaced) as its first argument; the
// running digest accumulates tD after every round (`digest += tD`), not once at the end;
// and six constants are one more than RFC 1321's T table (T2, T4, T18, T19, T20, T50 are
// printed as 0xE8C7B757, 0xC1BDCEEF, 0xC040B341, 0x265E5A52, 0xE9B6C7AB, 0x432AFF98).
// The 16 rounds are the first four steps of each of MD5's four rounds, with MD5's message
// word order (0,1,2,3 / 1,6,11,0 / 5,8,11,14 / 0,7,14,5) and shifts.
uvec4 md5rand16(uvec4 seed, uint key) {
  uint d00 = seed.x ^ key;
  uint d01 = seed.y ^ key;
  uint d02 = seed.z ^ key;
  uint d03 = seed.w ^ key;

  uvec4 digest = uvec4(0x01234567u, 0x89ABCDEFu, 0xFEDCBA98u, 0x76543210u);
  uvec4 tD = digest;
  uint Ft;
  uint rot_temp;

  Ft = (tD.x & tD.y) | ((~tD.x) & tD.z);
  // The number on the next line is sin(1) * 2^32; likewise the other blocks (thesis).
  rot_temp = tD.x + Ft + d00 + 0xD76AA478u;
  tD.x = tD.y + (rot_temp << 7u) + (rot_temp >> 25u);
  tD = tD.yzwx;
  digest += tD;

  Ft = (tD.x & tD.y) | ((~tD.x) & tD.z);
  rot_temp = tD.x + Ft + d01 + 0xE8C7B757u;
  tD.x = tD.y + (rot_temp << 12u) + (rot_temp >> 20u);
  tD = tD.yzwx;
  digest += tD;

  Ft = (tD.x & tD.y) | ((~tD.x) & tD.z);
  rot_temp = tD.x + Ft + d02 + 0x242070DBu;
  tD.x = tD.y + (rot_temp << 17u) + (rot_temp >> 15u);
  tD = tD.yzwx;
  digest += tD;

  Ft = (tD.x & tD.y) | ((~tD.x) & tD.z);
  rot_temp = tD.x + Ft + d03 + 0xC1BDCEEFu;
  tD.x = tD.y + (rot_temp << 22u) + (rot_temp >> 10u);
  tD = tD.yzwx;
  digest += tD;

  ////////////////////////////////////

  Ft = (tD.z & tD.x) | ((~tD.z) & tD.y);
  rot_temp = tD.x + Ft + d01 + 0xF61E2562u;
  tD.x = tD.y + (rot_temp << 5u) + (rot_temp >> 27u);
  tD = tD.yzwx;
  digest += tD;

  Ft = (tD.z & tD.x) | ((~tD.z) & tD.y);
  rot_temp = tD.x + Ft /* + d06 */ + 0xC040B341u;
  tD.x = tD.y + (rot_temp << 9u) + (rot_temp >> 23u);
  tD = tD.yzwx;
  digest += tD;

  Ft = (tD.z & tD.x) | ((~tD.z) & tD.y);
  rot_temp = tD.x + Ft /* + d11 */ + 0x265E5A52u;
  tD.x = tD.y + (rot_temp << 14u) + (rot_temp >> 18u);
  tD = tD.yzwx;
  digest += tD;

  Ft = (tD.z & tD.x) | ((~tD.z) & tD.y);
  rot_temp = tD.x + Ft + d00 + 0xE9B6C7ABu;
  tD.x = tD.y + (rot_temp << 20u) + (rot_temp >> 12u);
  tD = tD.yzwx;
  digest += tD;

  ////////////////////////////////////

  Ft = tD.x ^ tD.y ^ tD.z;
  rot_temp = tD.x + Ft /* + d05 */ + 0xFFFA3942u;
  tD.x = tD.y + (rot_temp << 4u) + (rot_temp >> 28u);
  tD = tD.yzwx;
  digest += tD;

  Ft = tD.x ^ tD.y ^ tD.z;
  rot_temp = tD.x + Ft /* + d08 */ + 0x8771F681u;
  tD.x = tD.y + (rot_temp << 11u) + (rot_temp >> 21u);
  tD = tD.yzwx;
  digest += tD;

  Ft = tD.x ^ tD.y ^ tD.z;
  rot_temp = tD.x + Ft /* + d11 */ + 0x6D9D6122u;
  tD.x = tD.y + (rot_temp << 16u) + (rot_temp >> 16u);
  tD = tD.yzwx;
  digest += tD;

  Ft = tD.x ^ tD.y ^ tD.z;
  rot_temp = tD.x + Ft /* + d14 */ + 0xFDE5380Cu;
  tD.x = tD.y + (rot_temp << 23u) + (rot_temp >> 9u);
  tD = tD.yzwx;
  digest += tD;

  ////////////////////////////////////

  Ft = tD.y ^ (tD.x | (~tD.z));
  rot_temp = tD.x + Ft + d00 + 0xF4292244u;
  tD.x = tD.y + (rot_temp << 6u) + (rot_temp >> 26u);
  tD = tD.yzwx;
  digest += tD;

  Ft = tD.y ^ (tD.x | (~tD.z));
  rot_temp = tD.x + Ft /* + d07 */ + 0x432AFF98u;
  tD.x = tD.y + (rot_temp << 10u) + (rot_temp >> 22u);
  tD = tD.yzwx;
  digest += tD;

  Ft = tD.y ^ (tD.x | (~tD.z));
  rot_temp = tD.x + Ft /* + d14 */ + 0xAB9423A7u;
  tD.x = tD.y + (rot_temp << 15u) + (rot_temp >> 17u);
  tD = tD.yzwx;
  digest += tD;

  Ft = tD.y ^ (tD.x | (~tD.z));
  rot_temp = tD.x + Ft /* + d05 */ + 0xFC93A039u;
  tD.x = tD.y + (rot_temp << 21u) + (rot_temp >> 11u);
  tD = tD.yzwx;
  digest += tD;

  return digest;
}

// Full MD5 (RFC 1321): the one 64-step compression of the 16-byte message whose four
// little-endian words are seed ^ key, i.e. exactly MD5 of those 16 bytes:
//   message words m0..m3 = seed ^ key, m4 = 0x80 (the padding byte 0x80 right after the
//   message, little-endian), m5..m13 = 0, m14 = 128 (message length in bits), m15 = 0;
//   initial state A, B, C, D = 0x67452301, 0xefcdab89, 0x98badcfe, 0x10325476;
//   the RFC's sine table and shifts; result = initial state + final state = (A, B, C, D),
// whose little-endian bytes are the usual MD5 digest bytes. This is what Tzeng & Wei (2008)
// use and what the thesis reduced to 16 rounds; it costs about four times as much.
const uint kMd5Sine[64] = uint[64](
    0xd76aa478u, 0xe8c7b756u, 0x242070dbu, 0xc1bdceeeu, 0xf57c0fafu, 0x4787c62au, 0xa8304613u,
    0xfd469501u, 0x698098d8u, 0x8b44f7afu, 0xffff5bb1u, 0x895cd7beu, 0x6b901122u, 0xfd987193u,
    0xa679438eu, 0x49b40821u, 0xf61e2562u, 0xc040b340u, 0x265e5a51u, 0xe9b6c7aau, 0xd62f105du,
    0x02441453u, 0xd8a1e681u, 0xe7d3fbc8u, 0x21e1cde6u, 0xc33707d6u, 0xf4d50d87u, 0x455a14edu,
    0xa9e3e905u, 0xfcefa3f8u, 0x676f02d9u, 0x8d2a4c8au, 0xfffa3942u, 0x8771f681u, 0x6d9d6122u,
    0xfde5380cu, 0xa4beea44u, 0x4bdecfa9u, 0xf6bb4b60u, 0xbebfbc70u, 0x289b7ec6u, 0xeaa127fau,
    0xd4ef3085u, 0x04881d05u, 0xd9d4d039u, 0xe6db99e5u, 0x1fa27cf8u, 0xc4ac5665u, 0xf4292244u,
    0x432aff97u, 0xab9423a7u, 0xfc93a039u, 0x655b59c3u, 0x8f0ccc92u, 0xffeff47du, 0x85845dd1u,
    0x6fa87e4fu, 0xfe2ce6e0u, 0xa3014314u, 0x4e0811a1u, 0xf7537e82u, 0xbd3af235u, 0x2ad7d2bbu,
    0xeb86d391u);
const uint kMd5Shift[16] = uint[16](7u, 12u, 17u, 22u, 5u, 9u, 14u, 20u, 4u, 11u, 16u, 23u,
                                    6u, 10u, 15u, 21u);

uvec4 md5rand64(uvec4 seed, uint key) {
  uint m[16] = uint[16](seed.x ^ key, seed.y ^ key, seed.z ^ key, seed.w ^ key, 0x80u, 0u, 0u,
                        0u, 0u, 0u, 0u, 0u, 0u, 0u, 128u, 0u);
  const uvec4 init = uvec4(0x67452301u, 0xefcdab89u, 0x98badcfeu, 0x10325476u);
  uint a = init.x, b = init.y, c = init.z, d = init.w;
  for (int i = 0; i < 64; ++i) {
    uint f;
    int word;
    if (i < 16) {
      f = (b & c) | (~b & d);
      word = i;
    } else if (i < 32) {
      f = (d & b) | (~d & c);
      word = (5 * i + 1) & 15;
    } else if (i < 48) {
      f = b ^ c ^ d;
      word = (3 * i + 5) & 15;
    } else {
      f = c ^ (b | ~d);
      word = (7 * i) & 15;
    }
    uint sum = a + f + kMd5Sine[i] + m[word];
    uint shift = kMd5Shift[(i >> 4) * 4 + (i & 3)];
    a = d;
    d = c;
    c = b;
    b = b + ((sum << shift) | (sum >> (32u - shift)));
  }
  return init + uvec4(a, b, c, d);
}

// pcg3d, Jarzynski & Olano 2020 (JCGT 9(3), "Hash Functions for GPU Rendering"), as
// published: an LCG step per word, then two rounds of cross-multiplication around an
// xorshift.
uvec3 pcg3d(uvec3 v) {
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

// pcg3d behind the same (seed, key) -> uvec4 interface as the MD5 variants. Our definition:
//   h   = pcg3d(uvec3(seed.x ^ (seed.w * 0x9E3779B9u), seed.y, seed.z ^ key))
//   out = uvec4(h, pcg3d(h).x)
// For the pipeline's seeds (x, y, 0, 0) the first three words are the paper's pcg3d of
// (x, y, key) unchanged. seed.w, which pcg3d has no room for, is folded into x after a
// multiplication by the golden-ratio constant (so (0,0,0,1) does not collide with
// (1,0,0,0)); the fourth word hashes the first three once more, which costs a second pcg3d
// but keeps all four words dependent on every input word.
uvec4 pcg3dRand(uvec4 seed, uint key) {
  uvec3 h = pcg3d(uvec3(seed.x ^ (seed.w * 0x9E3779B9u), seed.y, seed.z ^ key));
  return uvec4(h, pcg3d(h).x);
}

// ---- Hashes that teach by failing ----------------------------------------------

// The Appendix A listing cut to its first `steps` steps (4 or 8; 16 would be md5rand16): the
// same message words, constants as printed, shifts, digest start and `digest += tD` after
// every step. Written as a loop over the listing's tables so that the 16-step form can be
// checked against the literal md5rand16 above (tests/stages/test_hash.cpp).
const uint kThesisConstant[16] = uint[16](
    0xD76AA478u, 0xE8C7B757u, 0x242070DBu, 0xC1BDCEEFu, 0xF61E2562u, 0xC040B341u, 0x265E5A52u,
    0xE9B6C7ABu, 0xFFFA3942u, 0x8771F681u, 0x6D9D6122u, 0xFDE5380Cu, 0xF4292244u, 0x432AFF98u,
    0xAB9423A7u, 0xFC93A039u);
const uint kThesisShift[16] = uint[16](7u, 12u, 17u, 22u, 5u, 9u, 14u, 20u, 4u, 11u, 16u, 23u,
                                       6u, 10u, 15u, 21u);
// Message word of each step; 4 marks the words the listing comments out (zero).
const int kThesisWord[16] = int[16](0, 1, 2, 3, 1, 4, 4, 0, 4, 4, 4, 4, 0, 4, 4, 4);

uvec4 md5randSteps(uvec4 seed, uint key, int steps) {
  uint m[5] = uint[5](seed.x ^ key, seed.y ^ key, seed.z ^ key, seed.w ^ key, 0u);
  uvec4 digest = uvec4(0x01234567u, 0x89ABCDEFu, 0xFEDCBA98u, 0x76543210u);
  uvec4 tD = digest;
  for (int i = 0; i < steps; ++i) {
    uint Ft;
    if (i < 4) Ft = (tD.x & tD.y) | ((~tD.x) & tD.z);
    else if (i < 8) Ft = (tD.z & tD.x) | ((~tD.z) & tD.y);
    else if (i < 12) Ft = tD.x ^ tD.y ^ tD.z;
    else Ft = tD.y ^ (tD.x | (~tD.z));
    uint rot_temp = tD.x + Ft + m[kThesisWord[i]] + kThesisConstant[i];
    tD.x = tD.y + (rot_temp << kThesisShift[i]) + (rot_temp >> (32u - kThesisShift[i]));
    tD = tD.yzwx;
    digest += tD;
  }
  return digest;
}

// The pixel index a naive renderer seeds a per-pixel generator with: x + 4096 y (a 4096-wide
// image), the ray index above it, XOR the key (as Appendix A applies its key).
uint lcgPixelIndex(uvec4 seed, uint key) {
  return (seed.x + (seed.y << 12u) + (seed.z << 24u) + (seed.w << 28u)) ^ key;
}

// C rand()-style: the ISO C example generator (next = next * 1103515245 + 12345; return
// next / 65536 % 32768), srand(pixel index), four calls. Each 15-bit result is placed in the
// top bits of its word, so toUnitSquare gives rand() / 32768 as a C program would; the low
// 17 bits of every word are zero.
uvec4 lcg15Rand(uvec4 seed, uint key) {
  uint state = lcgPixelIndex(seed, key);
  uvec4 words;
  for (int i = 0; i < 4; ++i) {
    state = state * 1103515245u + 12345u;
    words[i] = ((state >> 16u) & 0x7FFFu) << 17u;
  }
  return words;
}

// 32-bit LCG of Numerical Recipes (a = 1664525, c = 1013904223), started at the pixel index,
// four steps; each word is the whole state.
uvec4 lcg32Rand(uvec4 seed, uint key) {
  uint state = lcgPixelIndex(seed, key);
  uvec4 words;
  for (int i = 0; i < 4; ++i) {
    state = state * 1664525u + 1013904223u;
    words[i] = state;
  }
  return words;
}

// xxhash32 of four words, as Jarzynski & Olano 2020 give it (from Collet's xxHash).
uint xxhash32(uvec4 p) {
  const uint PRIME32_2 = 2246822519u, PRIME32_3 = 3266489917u;
  const uint PRIME32_4 = 668265263u, PRIME32_5 = 374761393u;
  uint h32 = p.w + PRIME32_5 + p.x * PRIME32_3;
  h32 = PRIME32_4 * ((h32 << 17u) | (h32 >> 15u));
  h32 += p.y * PRIME32_3;
  h32 = PRIME32_4 * ((h32 << 17u) | (h32 >> 15u));
  h32 += p.z * PRIME32_3;
  h32 = PRIME32_4 * ((h32 << 17u) | (h32 >> 15u));
  h32 = PRIME32_2 * (h32 ^ (h32 >> 15u));
  h32 = PRIME32_3 * (h32 ^ (h32 >> 13u));
  return h32 ^ (h32 >> 16u);
}

// Four words from the 4-to-1 xxhash32: word i hashes (seed ^ key) with i added to w * 4
// (injective while seed.w < 2^30; the pipeline's seed.w is 0).
uvec4 xxhash32Rand(uvec4 seed, uint key) {
  uvec4 p = seed ^ uvec4(key);
  p.w *= 4u;
  return uvec4(xxhash32(p), xxhash32(p + uvec4(0u, 0u, 0u, 1u)),
               xxhash32(p + uvec4(0u, 0u, 0u, 2u)), xxhash32(p + uvec4(0u, 0u, 0u, 3u)));
}

// The hash selected by `light.hash` (HASH_* of shared/hash_kinds.h). A program compiled with
// HASH_KIND defined (the trace, PCSS, the hash view: hashSpecialization() in
// app/gl/hash_kind.h) has a constant kind, so the compiler keeps its case alone and the
// program holds the one hash it uses.
uvec4 hashRand(uvec4 seed, uint key, int hashKind) {
#ifdef HASH_KIND
  hashKind = HASH_KIND;
#endif
  switch (hashKind) {
    case HASH_MD5_64: return md5rand64(seed, key);
    case HASH_PCG3D: return pcg3dRand(seed, key);
    case HASH_MD5_4: return md5randSteps(seed, key, 4);
    case HASH_MD5_8: return md5randSteps(seed, key, 8);
    case HASH_LCG15: return lcg15Rand(seed, key);
    case HASH_LCG32: return lcg32Rand(seed, key);
    case HASH_XXHASH32: return xxhash32Rand(seed, key);
  }
  return md5rand16(seed, key);
}

// Two hash words -> a point of [0,1)^2: the top 24 bits of each word times 2^-24. 24 bits
// are exactly what a float holds, so the mapping is exact, uniform over 2^24 values per axis
// and never reaches 1.0 (the largest value is 1 - 2^-24); converting all 32 bits would round
// up to 1.0 for the top 128 words.
vec2 toUnitSquare(uvec2 bits) {
  return vec2(bits >> 8u) * (1.0 / 16777216.0);
}

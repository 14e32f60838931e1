#include "support/hash_stats_oracle.h"

#include <cmath>
#include <numeric>

#include "shared/hash_kinds.h"
#include "shared/hash_stats_layout.h"
#include "support/md5_reference.h"

namespace statsref {

void patternInput(int pattern, std::uint32_t i, std::uint32_t key, glm::uvec4& seed,
                  std::uint32_t& inputKey) {
  inputKey = key;
  switch (pattern) {
    case HASH_PATTERN_PIXELS:  // 1024 x 1024 image, then the next ray
      seed = {i % 1024, (i / 1024) % 1024, i / (1024 * 1024), 0};
      return;
    case HASH_PATTERN_MORTON: {  // bit 2k of i -> bit k of x, bit 2k+1 -> bit k of y
      std::uint32_t x = 0, y = 0;
      for (int k = 0; k < 16; ++k) {
        x |= ((i >> (2 * k)) & 1u) << k;
        y |= ((i >> (2 * k + 1)) & 1u) << k;
      }
      seed = {x, y, 0, 0};
      return;
    }
    case HASH_PATTERN_FRAMES:
      seed = {0, 0, 0, 0};
      inputKey = key * 16777216u + i;
      return;
    default: seed = {i + 1, 0, 0, 0};
  }
}

glm::uvec4 statsHash(glm::uvec4 seed, std::uint32_t key, int kind) {
  if (kind == HASH_STATS_IDENTITY) return seed;
  if (kind == HASH_STATS_CONSTANT) return glm::uvec4(0x5A5A5A5Au);
  return md5ref::hashRand(seed, key, kind);
}

std::vector<glm::uvec4> samples(int kind, int pattern, std::uint32_t count, std::uint32_t key) {
  std::vector<glm::uvec4> out(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    glm::uvec4 seed;
    std::uint32_t k;
    patternInput(pattern, i, key, seed, k);
    const glm::uvec4 h = statsHash(seed, k, kind);
    out[i] = {h.x, h.y, statsHash(seed + glm::uvec4(1, 0, 0, 0), k, kind).x,
              statsHash(seed, k + 1, kind).x};
  }
  return out;
}

namespace {
double unit(std::uint32_t word) { return double(word >> 8) / 16777216.0; }

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = double(a.size());
  const double ma = std::accumulate(a.begin(), a.end(), 0.0) / n;
  const double mb = std::accumulate(b.begin(), b.end(), 0.0) / n;
  double cov = 0, va = 0, vb = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    cov += (a[i] - ma) * (b[i] - mb);
    va += (a[i] - ma) * (a[i] - ma);
    vb += (b[i] - mb) * (b[i] - mb);
  }
  return va > 0 && vb > 0 ? cov / std::sqrt(va * vb) : 1.0;
}
}  // namespace

Oracle compute(const std::vector<glm::uvec4>& s, std::uint32_t chunk) {
  Oracle o;
  o.buckets.assign(1024, 0);
  o.pairs.assign(4096, 0);
  o.ones.assign(32, 0);
  std::vector<double> x, right, frame, nextA, nextB;
  for (size_t i = 0; i < s.size(); ++i) {
    o.buckets[s[i].x / 4194304u]++;                         // x / 2^22
    o.pairs[(s[i].y / 67108864u) * 64 + s[i].x / 67108864u]++;  // / 2^26
    for (int b = 0; b < 32; ++b) o.ones[b] += (s[i].x >> b) & 1u;
    x.push_back(unit(s[i].x));
    right.push_back(unit(s[i].z));
    frame.push_back(unit(s[i].w));
    if ((i + 1) % chunk != 0 && i + 1 < s.size()) {
      nextA.push_back(unit(s[i].x));
      nextB.push_back(unit(s[i + 1].x));
    }
  }
  const double n = double(s.size());
  for (auto c : o.buckets) o.chiBuckets += (c - n / 1024) * (c - n / 1024) / (n / 1024);
  for (auto c : o.pairs) o.chiPairs += (c - n / 4096) * (c - n / 4096) / (n / 4096);
  for (auto c : o.ones) o.chiBits += (c - n / 2) * (c - n / 2) / (n / 4);
  o.rNext = correlation(nextA, nextB);
  o.rRight = correlation(x, right);
  o.rFrame = correlation(x, frame);

  // FIPS 140-2 on the bit string of the x words, LSB first, 20,000 bits per block; blocks
  // never straddle chunks.
  double runsSum = 0;
  for (size_t start = 0; start + 625 <= s.size(); start += 625) {
    if (start / chunk != (start + 624) / chunk) continue;
    std::vector<int> bits;
    for (size_t w = start; w < start + 625; ++w)
      for (int b = 0; b < 32; ++b) bits.push_back((s[w].x >> b) & 1u);
    const int ones = std::accumulate(bits.begin(), bits.end(), 0);
    o.monobitFails += !(ones > 9725 && ones < 10275);
    std::array<double, 16> nibbles{};
    for (size_t k = 0; k < bits.size(); k += 4)
      nibbles[bits[k] | bits[k + 1] << 1 | bits[k + 2] << 2 | bits[k + 3] << 3] += 1;
    double sum = 0;
    for (double f : nibbles) sum += f * f;
    const double poker = 16.0 / 5000 * sum - 5000;
    o.pokerFails += !(poker > 2.16 && poker < 46.17);
    std::array<std::array<int, 7>, 2> runs{};  // [bit][length 1..6+]
    int longest = 0, total = 0;
    for (size_t k = 0; k < bits.size();) {
      size_t end = k;
      while (end < bits.size() && bits[end] == bits[k]) ++end;
      const int length = int(end - k);
      runs[bits[k]][std::min(length, 6)]++;
      longest = std::max(longest, length);
      ++total;
      k = end;
    }
    const int low[7] = {0, 2315, 1114, 527, 240, 103, 103};
    const int high[7] = {0, 2685, 1386, 723, 384, 209, 209};
    bool ok = longest < 26;
    for (int bit = 0; bit < 2; ++bit)
      for (int l = 1; l <= 6; ++l) ok = ok && runs[bit][l] >= low[l] && runs[bit][l] <= high[l];
    o.runsFails += !ok;
    runsSum += total - (1 + 19999 / 2.0);
    ++o.fipsBlocks;
  }
  o.runsZ = o.fipsBlocks ? runsSum / std::sqrt(o.fipsBlocks * 19999 / 4.0) : 0;
  return o;
}

std::vector<std::uint64_t> avalanche(int kind, int pattern, std::uint32_t inputs,
                                     std::uint32_t key) {
  std::vector<std::uint64_t> flips(32 * 32 + 32, 0);
  for (std::uint32_t i = 0; i < inputs; ++i) {
    glm::uvec4 seed;
    std::uint32_t k;
    patternInput(pattern, i, key, seed, k);
    const std::uint32_t base = statsHash(seed, k, kind).x;
    for (int in = 0; in < 32; ++in) {
      if (seed.x & (1u << in)) continue;  // each unordered pair of inputs once
      flips[32 * 32 + in]++;
      const glm::uvec4 flipped(seed.x + (1u << in), seed.y, seed.z, seed.w);
      const std::uint32_t change = base ^ statsHash(flipped, k, kind).x;
      for (int out = 0; out < 32; ++out) flips[in * 32 + out] += (change >> out) & 1u;
    }
  }
  return flips;
}

}  // namespace statsref

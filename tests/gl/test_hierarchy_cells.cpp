// The window and cell arithmetic the shaders compile (shaders/shared/hierarchy_cells.h), as
// C++ sees it (gl/hierarchy_cells.h), against brute force from the definitions: the N-buffer
// window of a texel is the 2^n-texel run (or the whole axis) nearest to starting a_n texels
// before it that lies inside the map (thesis §3.5, decision 003); a min-max cell is the set of
// level-0 texels with one quotient by 2^n (thesis §5.1). Every size 1..70, every level to one
// past the top.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <set>

#include "gl/hierarchy_cells.h"

namespace {

int power(int level) {
  int p = 1;
  for (int i = 0; i < level; ++i) p *= 2;
  return p;
}

// The window by search: every run of min(2^n, size) texels inside [0, size), the one whose
// start is nearest the centred start x - a_n.
glm::ivec2 bruteWindow(int level, int x, int size) {
  const int length = std::min(power(level), size), centred = x - (level == 0 ? 0 : power(level) / 2);
  int best = -1;
  for (int start = 0; start + length <= size; ++start)
    if (best < 0 || std::abs(start - centred) < std::abs(best - centred)) best = start;
  return {best, best + length - 1};
}

int bruteSpanning(int texels) {
  int level = 0;
  while (power(level) < texels) ++level;
  return level;
}

}  // namespace

TEST(HierarchyCells, NBufferWindowsMatchBruteForce) {
  for (int size = 1; size <= 70; ++size)
    for (int level = 0; level <= bruteSpanning(size) + 1; ++level)
      for (int x = 0; x < size; ++x) {
        const glm::ivec2 want = bruteWindow(level, x, size);
        ASSERT_EQ(cells::nbufferWindow1D(level, x, size), want)
            << "size " << size << " level " << level << " texel " << x;
        EXPECT_LE(want.x, x);  // a texel's window holds it
        EXPECT_GE(want.y, x);
      }
}

TEST(HierarchyCells, TexelForWindowHoldsThatWindow) {
  for (int size = 1; size <= 70; ++size)
    for (int level = 0; level <= bruteSpanning(size) + 1; ++level)
      for (int lo = -3; lo < size + 3; ++lo) {
        // The window asked for, clamped inward: the run starting nearest `lo`.
        const int length = std::min(power(level), size);
        const int start = std::max(0, std::min(lo, size - length));
        const int texel = cells::nbufferTexelForWindow(level, lo, size);
        ASSERT_GE(texel, 0);
        ASSERT_LT(texel, size);
        EXPECT_EQ(bruteWindow(level, texel, size), glm::ivec2(start, start + length - 1))
            << "size " << size << " level " << level << " lo " << lo;
      }
}

// The build (nbuffer_level.frag) takes level n from the level n-1 texels for the windows
// starting at lo and lo + 2^(n-1): together they cover exactly texel x's window.
TEST(HierarchyCells, TwoFinerWindowsTileEachWindow) {
  for (int size = 1; size <= 70; ++size)
    for (int level = 1; level <= bruteSpanning(size) + 1; ++level)
      for (int x = 0; x < size; ++x) {
        const glm::ivec2 window = bruteWindow(level, x, size);
        std::set<int> covered;
        for (int lo : {window.x, window.x + power(level - 1)}) {
          const glm::ivec2 finer = bruteWindow(level - 1, cells::nbufferTexelForWindow(level - 1, lo, size), size);
          for (int t = finer.x; t <= finer.y; ++t) covered.insert(t);
        }
        std::set<int> want;
        for (int t = window.x; t <= window.y; ++t) want.insert(t);
        EXPECT_EQ(covered, want) << "size " << size << " level " << level << " texel " << x;
      }
}

TEST(HierarchyCells, LevelSpanningAndWholeMap) {
  for (int texels = 1; texels <= 5000; ++texels) ASSERT_EQ(cells::levelSpanning(texels), bruteSpanning(texels)) << texels;
  for (int w = 1; w <= 40; ++w)
    for (int h = 1; h <= 40; h += 3) {
      const int top = bruteSpanning(std::max(w, h));
      const glm::ivec2 texel = cells::nbufferWholeMapTexel(top, {w, h});
      EXPECT_EQ(bruteWindow(top, texel.x, w), glm::ivec2(0, w - 1)) << w << "x" << h;
      EXPECT_EQ(bruteWindow(top, texel.y, h), glm::ivec2(0, h - 1)) << w << "x" << h;
    }
}

TEST(HierarchyCells, MinMaxCellsMatchBruteForce) {
  for (int size = 1; size <= 70; ++size)
    for (int level = 0; level <= bruteSpanning(size) + 1; ++level) {
      // Group the level-0 texels by their quotient by 2^n.
      std::vector<glm::ivec2> groups;
      for (int t = 0; t < size; ++t) {
        const int c = t / power(level);
        if (c == int(groups.size())) groups.push_back({t, t});
        groups[size_t(c)].y = t;
      }
      ASSERT_EQ(cells::minmaxLevelSize(level, size), int(groups.size())) << size << " " << level;
      for (int c = 0; c < int(groups.size()); ++c)
        EXPECT_EQ(cells::minmaxCell1D(level, c, size), groups[size_t(c)]) << size << " " << level << " " << c;
    }
  // One cell at the top level, more than one below it.
  for (int size = 2; size <= 70; ++size) {
    EXPECT_EQ(cells::minmaxLevelSize(cells::levelSpanning(size), size), 1) << size;
    EXPECT_GT(cells::minmaxLevelSize(cells::levelSpanning(size) - 1, size), 1) << size;
  }
}

// The stored base (GL's mip level m: max(1, floor(B / 2^m)) texels) holds level m + 1's
// ceil(size / 2^(m+1)) cells at every level, and no smaller base does: found by trying every
// base from ceil(size / 2) up, with GL's rounding written out; the mip count is GL's for
// that base (floor(log2(B)) + 1) and reaches the one-cell top level.
TEST(HierarchyCells, MinMaxBaseIsTheSmallestHoldingEveryLevel) {
  for (int size = 1; size <= 300; ++size) {
    const int top = bruteSpanning(size);
    auto holds = [&](int base) {
      for (int level = 1; level <= top; ++level) {
        const int mip = std::max(1, base / power(level - 1));
        if (mip < (size + power(level) - 1) / power(level)) return false;
      }
      return true;
    };
    int smallest = (size + 1) / 2;
    while (!holds(smallest)) ++smallest;
    EXPECT_EQ(cells::minmaxBaseSize(size), smallest) << size;
    int glLevels = 1;
    while (power(glLevels) <= smallest) ++glLevels;
    EXPECT_EQ(cells::minmaxMipLevels({size, 1}), std::max(top, 1)) << size;
    EXPECT_EQ(cells::minmaxMipLevels({1, size}), std::max(top, 1)) << size;
    if (size > 1) {
      EXPECT_EQ(glLevels, top) << size;  // every stored mip level is a hierarchy level
    }
  }
}

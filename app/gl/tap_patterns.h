// Tap patterns for filters over a square (PCSS's blocker search and PCF, Fernando 2005):
// points of [-1,1]^2, uploaded to the GPU as a storage buffer of vec2 and used as they are by
// the tests' brute-force oracles.
#pragma once
#include <glm/glm.hpp>

#include <vector>

enum class TapPattern { Regular, Poisson };

// n x n taps: a regular grid at the cell centres, or n^2 Poisson-disk points (Mitchell's
// best candidate, 16 candidates per point, fixed seed: the same points every run).
std::vector<glm::vec2> squareTaps(TapPattern pattern, int perSide);

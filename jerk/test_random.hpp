// jerk/test_random.hpp: seeded random draws shared by the jerk and axes tests.
// Input: a seeded std::mt19937_64 and a range. Output: a value spread evenly over the decades of
// the range (so 1e-4..1e4 mm is sampled as often near 1e-4 as near 1e4). Invariant: lo, hi > 0.
#pragma once

#include <cmath>
#include <random>

namespace ncsim::test {

/// A log-uniform draw in [lo, hi] (same unit as lo and hi).
inline double log_uniform(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(rng));
}

}  // namespace ncsim::test

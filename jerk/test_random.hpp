// jerk/test_random.hpp: seeded random draws shared by the jerk and axes tests.
// Input: a seeded std::mt19937_64 and a range. Output: a value spread evenly over the decades of
// the range (so 1e-4..1e4 mm is sampled as often near 1e-4 as near 1e4). Invariant: lo, hi > 0.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>

#include "jerk/jerk.hpp"

namespace ncsim::test {

/// A log-uniform draw in [lo, hi] (same unit as lo and hi).
inline double log_uniform(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(rng));
}

/// One move of issue 11's ranges: start, target position, arrival velocity, limits.
struct MoveDraw {
  jerk::State start;
  double p1 = 0.0;
  double v1 = 0.0;
  jerk::Limits lim;
};

/// Whether a MoveDraw arrives moving.
enum class Arrival { half, always };

/// Issue 11's ranges (distances 1e-4..1e4 mm, V 1..1e4 mm/s, A+ and A- 10..1e5 mm/s^2, J
/// 1e2..1e7 mm/s^3), starts inside the limits (|a| within the limit of its direction: A- where
/// it slows the motion, A+ where it speeds up), an arrival velocity in half of the draws or in
/// all (then never 0).
inline MoveDraw draw_move(std::mt19937_64& rng, Arrival arrival) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  MoveDraw d;
  d.lim = jerk::Limits{log_uniform(rng, 1.0, 1e4), log_uniform(rng, 10.0, 1e5),
                       log_uniform(rng, 10.0, 1e5), log_uniform(rng, 1e2, 1e7)};
  const double dist = log_uniform(rng, 1e-4, 1e4);
  d.start.p = 100.0 * u(rng);
  d.p1 = d.start.p + (u(rng) < 0.0 ? -dist : dist);
  d.start.v = u(rng) * d.lim.v_max;
  const double a = u(rng);
  const bool slows = a * d.start.v < 0.0;
  d.start.a = a * (slows ? d.lim.d_max : std::min(d.lim.a_max, d.lim.d_max));
  if (arrival == Arrival::half) {
    if (u(rng) < 0.0) d.v1 = u(rng) * d.lim.v_max;
  } else {
    do {
      d.v1 = u(rng) * d.lim.v_max;
    } while (d.v1 == 0.0);
  }
  return d;
}

}  // namespace ncsim::test

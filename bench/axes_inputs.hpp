#pragma once
// bench/axes_inputs: the seeded PTP requests of axes_bench and axes_digest (one definition, so
// the digest covers exactly the plans the benchmark times). Drawn up front from a seeded
// generator: the timed loops only plan.

#include <cstddef>
#include <random>
#include <vector>

#include "axes/profile.hpp"

namespace ncsim::bench {

/// One planning request of the benchmark.
struct AxesInput {
  axes::MotionState start;
  axes::PositionTarget target;
  axes::Dynamics dyn;
};

/// n requests (seed 42): V 100..5000 mm/s, A+ and A- 500..20500 mm/s^2, J 5e3..1e6 mm/s^3,
/// targets within +-1000 mm of 0. `moving`: starts with |v| <= V/2 and |a| <= A+/10, a quarter
/// of them arriving with a velocity |v1| <= V/2; else rest to rest.
inline std::vector<AxesInput> make_axes_inputs(bool moving, std::size_t n) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<AxesInput> out(n);
  for (auto& in : out) {
    in.dyn = {100.0 + 4900.0 * u(rng), 500.0 + 20000.0 * u(rng), 500.0 + 20000.0 * u(rng),
              5000.0 + 1e6 * u(rng)};
    in.target.p = (u(rng) - 0.5) * 2000.0;
    if (moving) {
      in.start.v = (u(rng) - 0.5) * in.dyn.v_max;
      in.start.a = (u(rng) - 0.5) * 0.2 * in.dyn.a_max;
      if (u(rng) < 0.25) in.target.v = (u(rng) - 0.5) * in.dyn.v_max;
    }
  }
  return out;
}

}  // namespace ncsim::bench

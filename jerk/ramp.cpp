// jerk/ramp.cpp: the out-of-line parts of the velocity change: validity of limits, time and
// distance of a change, stopping distance (see jerk.hpp; the ramp itself: ramp_inline.hpp).

#include <cmath>
#include <limits>

#include "jerk/jerk.hpp"

namespace ncsim::jerk {

bool valid(const Limits& limits) noexcept {
  // Finite and > 0 as two comparisons (NaN fails both).
  constexpr double kBig = std::numeric_limits<double>::max();
  const auto positive = [](double x) { return x > 0.0 && x <= kBig; };
  return positive(limits.v_max) && positive(limits.a_max) && positive(limits.d_max) &&
         positive(limits.j_max);
}

TimeDistance velocity_change(double v0, double a0, double v1, double a_lim, double j) noexcept {
  const Ramp ramp = velocity_ramp(v0, a0, v1, a_lim, a_lim, j);
  return TimeDistance{ramp.time(), distance(v0, a0, ramp)};
}

TimeDistance stopping_distance(double v0, double a0, double d_max, double j) noexcept {
  return velocity_change(v0, a0, 0.0, d_max, j);
}

}  // namespace ncsim::jerk

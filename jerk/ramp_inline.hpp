#pragma once
// jerk/ramp_inline: the bodies of the small functions of jerk.hpp that every planner calls in
// its inner loops (advance, velocity_ramp, distance, ramp_distance). They are inline so the
// axes' planners keep their speed across the library boundary (git history of
// docs/benchmarks.md); the contracts are documented in jerk.hpp. Included by jerk.hpp only.

#include <algorithm>
#include <cmath>

#include "core/tolerance.hpp"

namespace ncsim::jerk {

namespace detail {
// Weight of the stale end of a root bracket when the same end moved twice in a row
// (Anderson-Bjorck: 1 - g_new / g_replaced; Illinois' 1/2 where that is not in (0, 1)). It
// converges in fewer steps than Illinois' constant 1/2 on the convex distance functions.
inline double anderson_bjorck(double g_new, double g_replaced) noexcept {
  const double m = 1.0 - g_new / g_replaced;
  return m > 0.0 ? m : 0.5;
}
}  // namespace detail

inline State advance(const State& s, double j, double dt) noexcept {
  return State{s.p + dt * (s.v + dt * (s.a * 0.5 + dt * j * (1.0 / 6.0))),
               s.v + dt * (s.a + dt * j * 0.5), s.a + dt * j};
}

namespace detail {
// velocity_ramp with the start's release velocity v_zero = v0 + a0 |a0| / (2j) given: a level
// search ramps from one start to many end velocities and computes it once (the same value, so
// the same ramp bit for bit; issue 36: a division per level).
inline Ramp velocity_ramp_released(double v0, double a0, double v_zero, double v1, double a_up,
                                   double a_down, double j) noexcept {
  // The velocity reached when the acceleration is taken to zero at once (v_zero) decides the
  // direction of the pulse; everything below is in that direction (sign s).
  Ramp out;
  out.v_end = v1;
  const double s = v1 >= v_zero ? 1.0 : -1.0;
  const double a_lim = s > 0.0 ? a_up : a_down;
  const double a_s = s * a0;        // start acceleration in the pulse's direction
  const double dv = s * (v1 - v0);  // velocity change in the pulse's direction
  if (a_s > a_lim) {
    // Beyond the limit: back to it with j first (limits first), hold, reduce to zero. The
    // hold's velocity change is s (v1 - v_zero) >= 0.
    const double dv_ramps = a_s * a_s / (2.0 * j);
    const double dv_hold = dv - dv_ramps;
    out.jerk = {-s * j, 0.0, -s * j};
    out.duration = {(a_s - a_lim) / j,
                    dv_hold > kResidue * (std::abs(dv) + dv_ramps) ? dv_hold / a_lim : 0.0,
                    a_lim / j};
    out.a_peak = s * a_lim;
    return out;
  }
  // Where v1 is v_zero to rounding (the pulse only releases a start acceleration against it)
  // the radicand is a rounding residue, whose root would be a spurious pulse of sqrt(eps)
  // relative size: taken as 0 (docs/axes-profile.md, "Numerics" 5).
  const double radicand = j * dv + 0.5 * a_s * a_s;
  double a_peak =
      radicand > kResidue * (std::abs(j * dv) + 0.5 * a_s * a_s) ? std::sqrt(radicand) : 0.0;
  double t_hold = 0.0;
  if (a_peak > a_lim) {
    a_peak = a_lim;
    const double dv_ramps = (2.0 * a_peak * a_peak - a_s * a_s) / (2.0 * j);  // [mm/s]
    const double dv_hold = dv - dv_ramps;
    if (dv_hold > kResidue * (std::abs(dv) + std::abs(dv_ramps))) t_hold = dv_hold / a_peak;
  }
  const double da_up = a_peak - a_s;  // acceleration change of phase 1 [mm/s^2]
  out.jerk = {s * j, 0.0, -s * j};
  out.duration = {da_up > kResidue * a_peak ? da_up / j : 0.0, t_hold, a_peak / j};
  out.a_peak = s * a_peak;
  return out;
}
}  // namespace detail

inline Ramp velocity_ramp(double v0, double a0, double v1, double a_up, double a_down,
                          double j) noexcept {
  return detail::velocity_ramp_released(v0, a0, v0 + a0 * std::abs(a0) / (2.0 * j), v1, a_up,
                                        a_down, j);
}

inline double distance(double v0, double a0, const Ramp& ramp) noexcept {
  State st{0.0, v0, a0};
  for (std::size_t i = 0; i < 3; ++i)
    st = advance(st, ramp.jerk[i], ramp.duration[i]);
  return st.p;
}

inline double ramp_distance(double v, double a_lim, double j) noexcept {
  // Symmetric S-ramp from rest to v: the mean velocity is v/2 over the ramp time.
  if (v * j <= a_lim * a_lim) return v * std::sqrt(v / j);
  return 0.5 * v * (v / a_lim + a_lim / j);
}

}  // namespace ncsim::jerk

// jerk/reverse.cpp: moves that turn round once before arriving at a velocity v1 != 0 (see
// jerk.hpp, "ptp additions").
//
// With g = sign(v1): the first part (frame -g) changes the start to the level L > 0 in the
// direction -g (through v = 0 with the path limits where the start moves the other way),
// cruises there, and the second part (frame g) takes (-L, 0) through v = 0 to (v1, 0). The
// displacement toward g without cruise, s(L), falls as L grows (the detour grows); the
// fastest turn is at the highest level whose displacement still reaches the target,
// s(L) = g (p1 - p0), found by regula falsi (Anderson-Bjorck) on (0, V] (a cruise at V when s(V) is
// still beyond the target).

#include <algorithm>
#include <cmath>
#include <limits>

#include "jerk/jerk.hpp"

namespace ncsim::jerk {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Frame change (v0, a0) -> (level > = 0, 0): through v = 0 with the path limits where the
// frame start moves backward, else one ramp (under min(A+, A-) when it crosses v = 0).
void ramp_to(double v0, double a0, double level, const Limits& lim, Crossing& cross,
             Ramp& ramp) noexcept {
  cross = Crossing{};
  if ((v0 < 0.0 || a0 < 0.0) && level > 0.0 && crossing_ramp(v0, a0, level, lim, cross, ramp)) {
    return;
  }
  cross = Crossing{};
  const double a_up =
      v0 < 0.0 ? (level > 0.0 ? std::min(lim.a_max, lim.d_max) : lim.d_max) : lim.a_max;
  ramp = velocity_ramp(v0, a0, level, a_up, lim.d_max, lim.j_max);
}

Reversal make(const State& start, double g, double level, double v1, const Limits& lim) noexcept {
  Reversal r;
  r.out.sign = -g;
  ramp_to(-g * start.v, -g * start.a, level, lim, r.out.cross, r.out.first);
  r.out.v_level = level;
  r.out.second = Ramp{};
  r.out.second.v_end = level;
  r.back.sign = g;
  ramp_to(-level, 0.0, g * v1, lim, r.back.cross, r.back.first);
  r.back.v_level = g * v1;
  r.back.second = Ramp{};
  r.back.second.v_end = g * v1;
  return r;
}

// Displacement toward g of the turn at `level` without cruise.
double reach(const State& start, const Reversal& r, double g) noexcept {
  const State mid = end_state(start, r.out);
  return g * (end_state(mid, r.back).p - start.p);
}

}  // namespace

Status reversal_move(const State& start, double p1, double v1, const Limits& lim,
                     Reversal& out) noexcept {
  if (!valid(lim) || !std::isfinite(start.p) || !std::isfinite(start.v) ||
      !std::isfinite(start.a) || !std::isfinite(p1) || !std::isfinite(v1) ||
      std::abs(v1) > lim.v_max) {
    return Status::invalid_input;
  }
  if (v1 == 0.0) return Status::not_supported;
  const double g = v1 > 0.0 ? 1.0 : -1.0;
  const double d = g * (p1 - start.p);
  const auto f = [&](double level) { return reach(start, make(start, g, level, v1, lim), g) - d; };
  const double f_top = f(lim.v_max);
  double level = lim.v_max;
  if (f_top < 0.0) {
    double lo = 0.0;  // f > 0 side (a shorter detour still overshoots the target)
    double hi = lim.v_max;
    double f_lo = f(0.0);
    double f_hi = f_top;
    if (!(f_lo > 0.0)) return Status::not_supported;  // no detour needed (or none helps)
    int side = 0;
    const double tol = 8.0 * kEps * std::abs(d);
    for (int i = 0; i < 200 && hi - lo > 4.0 * kEps * hi; ++i) {
      double x = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
      if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
      const double fx = f(x);
      if (fx >= 0.0) {
        if (fx <= tol) {
          lo = x;
          break;
        }
        if (side == -1) f_hi *= detail::anderson_bjorck(fx, f_lo);
        lo = x;
        f_lo = fx;
        side = -1;
      } else {
        if (side == 1) f_lo *= detail::anderson_bjorck(fx, f_hi);
        hi = x;
        f_hi = fx;
        side = 1;
      }
    }
    level = lo;  // reach >= d: the rest is a (rounding-size) cruise backward
  }
  if (!(level > 0.0)) return Status::not_supported;
  out = make(start, g, level, v1, lim);
  const double rest = f(level);  // >= 0: covered by cruising backward at the level
  out.out.t_cruise = rest > 8.0 * kEps * std::abs(d) ? rest / level : 0.0;
  return Status::ok;
}

}  // namespace ncsim::jerk

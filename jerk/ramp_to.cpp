// jerk/ramp_to.cpp: the time-optimal velocity change from (v0, a0) to (v1, a1), its state at a
// time and its cut at a distance (see jerk.hpp, "planner-c2 additions").
//
// Method. For a duration T the accelerations a(t) with |a'| <= j, a(0) = a0, a(T) = a1 and a
// within [-a_down, a_up] form a convex set; its pointwise largest member is the upper envelope
// min(a0 + j t, a1 + j (T - t), a_up), the smallest the mirrored lower one, so the velocity
// changes reachable in T are the interval between their areas. The fastest change to dv is
// therefore an envelope: jerk +j from a0 to the peak, [hold at a_up], jerk -j to a1, with
//     dv = (2 a_p^2 - a0^2 - a1^2) / (2 j) + a_p t_hold,
// whose peak a_p >= max(a0, a1) exists exactly when dv >= dv_direct (the single jerk from a0
// to a1: a_p = max(a0, a1)); below dv_direct the trough, mirrored. The peak is the positive
// root even where a0 and a1 are both negative: a velocity gain above dv_direct then needs a
// positive acceleration somewhere, and the time jumps at dv = dv_direct (a real property of
// the problem, not of the method; jerk/ramp_to_test.cpp checks it against a scan of T).

#include <algorithm>
#include <cmath>

#include "jerk/jerk.hpp"

namespace ncsim::jerk {

StateRamp velocity_ramp_to(double v0, double a0, double v1, double a1, double a_up, double a_down,
                           double j) noexcept {
  a0 = std::clamp(a0, -a_down, a_up);
  a1 = std::clamp(a1, -a_down, a_up);
  StateRamp out;
  out.v_end = v1;
  out.a_end = a1;
  const double dv = v1 - v0;
  const double dv_direct = 0.5 * (a0 + a1) * std::abs(a1 - a0) / j;
  const double squares = 0.5 * (a0 * a0 + a1 * a1);  // [mm^2/s^4]
  if (std::abs(dv - dv_direct) <= kResidue * (std::abs(dv) + squares / j)) {
    // The single jerk from a0 to a1 (to rounding): no pulse.
    out.jerk = {a1 >= a0 ? j : -j, 0.0, 0.0};
    out.duration = {std::abs(a1 - a0) / j, 0.0, 0.0};
    out.a_peak = a1;
    return out;
  }
  // Everything below in the pulse's direction (sign s): b0, b1 the boundary accelerations,
  // w = j s dv the scaled velocity change, lim the limit the pulse runs into.
  const double s = dv > dv_direct ? 1.0 : -1.0;
  const double b0 = s * a0;
  const double b1 = s * a1;
  const double lim = s > 0.0 ? a_up : a_down;
  const double w = j * s * dv;
  // w + squares >= max(b0, b1)^2 here (w >= j s dv_direct), so the root is >= max(b0, b1).
  double peak = std::sqrt(std::max(0.0, w + squares));
  double t_hold = 0.0;
  if (peak > lim) {
    peak = lim;
    const double w_ramps = lim * lim - squares;  // j times the ramps' change
    const double w_hold = w - w_ramps;
    if (w_hold > kResidue * (std::abs(w) + std::abs(w_ramps))) t_hold = w_hold / (j * lim);
  }
  const double up = peak - b0;
  const double down = peak - b1;
  out.jerk = {s * j, 0.0, -s * j};
  out.duration = {up > kResidue * std::abs(peak) ? up / j : 0.0, t_hold,
                  down > kResidue * std::abs(peak) ? down / j : 0.0};
  out.a_peak = s * peak;
  return out;
}

double distance(double v0, double a0, const StateRamp& ramp) noexcept {
  State st{0.0, v0, a0};
  for (std::size_t i = 0; i < 3; ++i)
    st = advance(st, ramp.jerk[i], ramp.duration[i]);
  return st.p;
}

State state_at(double v0, double a0, const StateRamp& ramp, double t) noexcept {
  t = std::clamp(t, 0.0, ramp.time());
  State st{0.0, v0, a0};
  for (std::size_t i = 0; i < 3; ++i) {
    if (t <= ramp.duration[i]) return advance(st, ramp.jerk[i], t);
    st = advance(st, ramp.jerk[i], ramp.duration[i]);
    st.a = i < 2 ? ramp.a_peak : ramp.a_end;
    t -= ramp.duration[i];
  }
  st.v = ramp.v_end;
  return st;
}

double time_at_distance(double v0, double a0, const StateRamp& ramp, double s) noexcept {
  if (!(s > 0.0)) return 0.0;
  State st{0.0, v0, a0};
  double t0 = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    const double dur = ramp.duration[i];
    const State end = advance(st, ramp.jerk[i], dur);
    if (end.p >= s) {
      // p is continuous and (v >= 0) nondecreasing on the phase: the first t with p(t) >= s.
      double lo = 0.0;
      double hi = dur;
      for (int k = 0; k < 200 && hi - lo > 0.0; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break;
        (advance(st, ramp.jerk[i], mid).p >= s ? hi : lo) = mid;
      }
      return t0 + hi;
    }
    st = end;
    st.a = i < 2 ? ramp.a_peak : ramp.a_end;
    t0 += dur;
  }
  return ramp.time();
}

}  // namespace ncsim::jerk

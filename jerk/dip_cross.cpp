// jerk/dip_cross.cpp: braking through v = 0 with a free peak (see jerk.hpp, DipCrossing;
// docs/axes-profile.md, "Shape-free reference (LP)", "Found, then built").
//
// In the frame of the arrival velocity (g = sign(v1), start u0 = g v0 < 0 moving against it,
// braking with b0 = g a0 in (0, A-], end w1 = |v1| > 0, distance D = g (p1 - p0)), the
// acceleration stays >= 0 and the velocity rises monotonically from u0 to w1: jerk -J from b0
// down to the dip x (the braking eases), then the time-optimal crossing from the dip's end
// (v_x, x) through v = 0 (crossing_ramp: jerk +J to a peak, [hold at A-], jerk -J to a_z at
// v = 0, then under A+ to (w1, 0)), with
//     v_x = u0 + (b0^2 - x^2) / (2J),
// and a_z = min(A-, A+, sqrt(2 J w1), sqrt(2 x^2 - b0^2 - 2 J u0)). Which limits the member
// reaches (the peak A- or below, a_z at A-, at A+ or released, the rest's hold at A+ or its
// free peak) is decided by crossing_ramp's pieces, each in its own function there
// (crossing_phases, velocity_ramp). The dip ranges over [x_lo, b0]:
//     x_lo = sqrt(max(0, b0^2 + 2 J u0))
// is where the easing alone reaches v = 0 (0 where releasing b0 keeps v < 0: x = 0 is then the
// turn at the release velocity, reversal_move's kink), x = b0 is crossing_ramp from the start.
// The crossing reaches v = 0 with at least x_lo (crossing_start's a_z_min, the same for every
// x), so the family exists only where x_lo <= min(A-, A+, sqrt(2 J w1)).
// The smaller the dip, the longer the motion stays against v1 and the longer it takes: the time
// falls with x (seen on every draw of dip_cross_test.cpp), so the fastest member meeting the
// target is the root of d(x) = D with the largest x. The distance d(x) is not monotone (it
// rises, falls and, where the crossing's case changes, rises again), so that root is looked for
// from the top down over the cells of a grid and solved in the first cell whose ends differ in
// sign, by the bracketed solver of the level searches (jerk/root.hpp). Before the scan, three
// decisions from the two ends: the slowest member (x_lo) bounds every member's time and so,
// by the limits alone, the distances the family covers (within_reach); the fastest (x = b0)
// must beat the time found elsewhere; and the two ends bound every member's velocity (the
// fastest from above, crossing_ramp's upper envelope; the slowest from below; both checked in
// dip_cross_test.cpp), so d_lo - w1 dt <= d(x) <= d_hi + w1 dt, dt = t_lo - t_hi.

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/tolerance.hpp"
#include "jerk/crossing.hpp"
#include "jerk/jerk.hpp"
#include "jerk/root.hpp"
#include "jerk/trusted.hpp"

namespace ncsim::jerk {

namespace {

// Cells of the grid over the dip on which the largest root is looked for (its cost: a member
// evaluation each, only where the bounds before it leave the target within reach and the
// fastest member beats the best time found). 8 and 16 cells missed the fastest root in some of
// dip_cross_test.cpp's 2000 draws, 32 in none.
constexpr int kCells = 32;

// The family's frame (sign of v1) and its constants.
struct Frame {
  double g = 1.0;     // world direction of the frame
  double u0 = 0.0;    // start velocity, < 0 [mm/s]
  double b0 = 0.0;    // start acceleration, in (0, A-] [mm/s^2]
  double w1 = 0.0;    // end velocity, > 0 [mm/s]
  double x_lo = 0.0;  // the lowest dip [mm/s^2]
};

// The shape's applicability (no member evaluated): a start moving against v1 and braking within
// A- and V, whose crossing can reach v = 0 with no more than v1 and the limits allow.
bool frame_of(const State& start, double v1, const Limits& lim, Frame& f) noexcept {
  if (v1 == 0.0) return false;
  f.g = v1 > 0.0 ? 1.0 : -1.0;
  f.u0 = f.g * start.v;
  f.b0 = f.g * start.a;
  f.w1 = std::abs(v1);
  if (!(f.u0 < 0.0) || !(f.b0 > 0.0) || f.b0 > lim.d_max || -f.u0 > lim.v_max) return false;
  f.x_lo = std::sqrt(std::max(0.0, f.b0 * f.b0 + 2.0 * lim.j_max * f.u0));
  const double a_cap = std::min({lim.d_max, lim.a_max, std::sqrt(2.0 * lim.j_max * f.w1)});
  return !(f.x_lo > a_cap);
}

// The rest from (0, a_z) to (w1, 0) under A+ where the dip itself ends at v = 0 (no crossing
// phases): crossing_from's rest (the bare release where a_z is exactly sqrt(2 J w1)).
Ramp rest_from(double a_z, double w1, const Limits& lim) noexcept {
  const double j = lim.j_max;
  if (a_z == std::sqrt(2.0 * j * w1)) {
    Ramp rest;
    rest.jerk = {j, 0.0, -j};
    rest.duration = {0.0, 0.0, a_z / j};
    rest.a_peak = a_z;
    rest.v_end = w1;
    return rest;
  }
  return velocity_ramp(0.0, a_z, w1, lim.a_max, lim.d_max, j);
}

// The member with dip x into `out` (every member but `sign` written); returns the distance it
// covers in the frame [mm], NaN where the crossing does not exist (rounding at x_lo).
double member(const Frame& f, double x, const Limits& lim, DipCrossing& out) noexcept {
  const double j = lim.j_max;
  const double ease = f.b0 - x;
  out.jerk = -j;
  out.t_cruise = 0.0;
  out.dip = ease > kResidue * f.b0 ? ease / j : 0.0;
  out.a_dip = x;
  State s = advance(State{0.0, f.u0, f.b0}, -j, out.dip);
  s.a = x;
  if (s.v < 0.0) {
    double d_cross = 0.0;
    if (!detail::crossing_from(detail::crossing_start(s.v, x, lim, false), f.w1, lim, out.cross,
                               out.rest, &d_cross)) {
      return std::numeric_limits<double>::quiet_NaN();
    }
    return s.p + d_cross + distance(0.0, out.cross.a_zero, out.rest);
  }
  // The dip ends at v = 0 (x = x_lo to rounding): no crossing phases.
  out.cross = Crossing{};
  out.cross.a_zero = x;
  out.rest = rest_from(x, f.w1, lim);
  return s.p + distance(0.0, x, out.rest);
}

// Whether a member taking at most t_lo [s] can cover the distance d [mm]: the velocity rises
// monotonically from u0 < 0 to w1 > 0 with an acceleration of at most max(A+, A-), so it
// spends at least (w1 - u0) / a_hi of its time t on the change and covers
//     u0 t + c <= d(x) <= w1 t - c,  c = (w1 - u0)^2 / (2 a_hi),
// and t <= t_lo widens both sides. A margin of kRelTol keeps rounding on the safe side.
bool within_reach(const Frame& f, const Limits& lim, double d, double t_lo) noexcept {
  const double dv = f.w1 - f.u0;
  const double c = dv * dv / (2.0 * std::max(lim.a_max, lim.d_max));
  const double margin = kRelTol * (f.w1 - f.u0) * t_lo;
  return d <= f.w1 * t_lo - c + margin && d >= f.u0 * t_lo + c - margin;
}

// The member in the cell [x_a, x_b] (g = d(x) - D changes its sign between them) where
// d(x) = D, into `out`: the bracketed solver of the level searches (jerk/root.hpp; without
// slopes: regula falsi with the Anderson-Bjorck weight) on the cell.
void solve_cell(const Frame& f, const Limits& lim, double d, double tol, double x_a, double g_a,
                double x_b, double g_b, DipCrossing& out) noexcept {
  double last = x_a;
  const auto gs = [&](double x, double& slope) {
    slope = std::numeric_limits<double>::quiet_NaN();
    last = x;
    return member(f, x, lim, out) - d;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const bool a_neg = g_a < 0.0;
  const double x = detail::solve_with_slope(a_neg ? x_a : x_b, a_neg ? x_b : x_a, a_neg ? g_a : g_b,
                                            a_neg ? g_b : g_a, nan, nan, tol, gs);
  if (last != x) member(f, x, lim, out);
}

}  // namespace

bool detail::dip_crossing_applies(const State& start, double v1, const Limits& lim) noexcept {
  Frame f;
  return frame_of(start, v1, lim, f);
}

Status dip_crossing_move(const State& start, double p1, double v1, const Limits& lim,
                         DipCrossing& out) noexcept {
  if (!valid(lim) || !std::isfinite(start.p) || !std::isfinite(start.v) ||
      !std::isfinite(start.a) || !std::isfinite(p1) || !std::isfinite(v1) ||
      std::abs(v1) > lim.v_max) {
    return Status::invalid_input;
  }
  return detail::dip_crossing_move_trusted(start, p1, v1, lim,
                                           std::numeric_limits<double>::infinity(), out);
}

Status detail::dip_crossing_move_trusted(const State& start, double p1, double v1,
                                         const Limits& lim, double t_max,
                                         DipCrossing& out) noexcept {
  Frame f;
  if (!frame_of(start, v1, lim, f)) return Status::not_supported;
  const double d = f.g * (p1 - start.p);
  out.sign = f.g;
  // The slowest member (the lowest dip) first: its time bounds every member's, and so the
  // distances the family can cover (most targets of a braking start lie far outside them).
  const double d_lo = member(f, f.x_lo, lim, out);
  const double t_lo = out.time();
  if (!std::isnan(d_lo) && !within_reach(f, lim, d, t_lo)) return Status::not_supported;
  // The fastest member (no dip): where it is not faster than t_max no member is.
  const double d_hi = member(f, f.b0, lim, out);
  if (!(out.time() < t_max) || std::isnan(d_hi)) return Status::not_supported;
  // The two ends bound every member's velocity (the fastest from above, the slowest from below:
  // dip_cross_test.cpp), so d_lo - w1 dt <= d(x) <= d_hi + w1 dt, dt = t_lo - t_hi.
  if (!std::isnan(d_lo)) {
    const double slack = f.w1 * (t_lo - out.time()) + kRelTol * (f.w1 - f.u0) * t_lo;
    if (d > d_hi + slack || d < d_lo - slack) return Status::not_supported;
  }
  // The fastest member meeting the target is the root of d(x) = D with the largest dip
  // acceleration x. d is not monotone (it rises, falls and, past a change of the crossing's
  // case, rises again: dip_cross_test.cpp), so the cells of a grid over [x_lo, b0] are
  // checked for a change of sign from the top down, and the first cell with one is solved.
  // A pair of roots inside one cell is not seen (a faster member missed, never an invalid one).
  const double tol = kResidue * std::max(std::abs(d), std::abs(d_hi));
  double x_top = f.b0;
  double g_top = d_hi - d;
  if (g_top == 0.0) return Status::ok;
  for (int k = kCells - 1; k >= 0; --k) {
    const double x = f.x_lo + (f.b0 - f.x_lo) * k / kCells;
    const double gx = (k == 0 ? d_lo : member(f, x, lim, out)) - d;
    if (std::isnan(gx)) break;
    if (gx == 0.0) {
      if (k == 0) member(f, x, lim, out);
      return Status::ok;
    }
    if ((gx < 0.0) != (g_top < 0.0)) {
      solve_cell(f, lim, d, tol, x, gx, x_top, g_top, out);
      return Status::ok;
    }
    x_top = x;
    g_top = gx;
  }
  return Status::not_supported;
}

State end_state(const State& start, const DipCrossing& dc) noexcept {
  // Each phase starts from its intended boundary values (as end_state of a Move).
  const double s = dc.sign;
  State st{s * start.p, s * start.v, s * start.a};
  st = advance(st, dc.jerk, dc.dip);
  st.a = dc.a_dip;
  if (dc.cross.time() > 0.0) {
    st = advance(st, dc.cross.jerk[0], dc.cross.duration[0]);
    st.a = dc.cross.a_peak;
    st = advance(st, dc.cross.jerk[1], dc.cross.duration[1]);
    st.a = dc.cross.a_peak;
    st = advance(st, dc.cross.jerk[2], dc.cross.duration[2]);
  }
  st.a = dc.cross.a_zero;
  st.v = 0.0;
  const Ramp& r = dc.rest;
  st = advance(st, r.jerk[0], r.duration[0]);
  st.a = r.a_peak;
  st = advance(st, r.jerk[1], r.duration[1]);
  st.a = r.a_peak;
  st = advance(st, r.jerk[2], r.duration[2]);
  st.a = 0.0;
  st.v = r.v_end;
  st = advance(st, 0.0, dc.t_cruise);
  return State{s * st.p, s * st.v, s * st.a};
}

Status dip_crossing_of_duration(const State& start, double p1, double v1, double duration,
                                const Limits& lim, DipCrossing& out) noexcept {
  if (!std::isfinite(duration) || duration < 0.0) return Status::invalid_input;
  DipCrossing fastest;
  const Status st = dip_crossing_move(start, p1, v1, lim, fastest);
  if (st != Status::ok) return st;
  const double t_min = fastest.time();
  if (duration <= t_min) {
    if (duration < t_min * (1.0 - kRelRounding)) return Status::too_short;
    out = fastest;
    return Status::ok;
  }
  // T(tau) = time of the fastest member meeting p1 - v1 tau, plus tau; T(0) = t_min < duration,
  // T(tau) >= tau. Where no member meets the moved target (it leaves the family's reach) the
  // cruise counts as too long. Bisection between the last tau found short and the first long.
  DipCrossing dc;
  const auto too_long = [&](double tau) {
    if (dip_crossing_move(start, p1 - v1 * tau, v1, lim, dc) != Status::ok) return true;
    return dc.time() + tau >= duration;
  };
  double lo = 0.0;
  double hi = duration;  // T(duration) >= duration (or no member)
  for (int i = 0; i < 200 && hi - lo > kMachineEpsilon * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (too_long(mid) ? hi : lo) = mid;
  }
  for (const double tau : {lo, hi}) {
    if (dip_crossing_move(start, p1 - v1 * tau, v1, lim, dc) != Status::ok) continue;
    if (std::abs(dc.time() + tau - duration) <= kRelRounding * duration) {
      out = dc;
      out.t_cruise = tau;
      return Status::ok;
    }
  }
  return Status::not_supported;  // T jumps over the duration (the fastest root changed branch)
}

}  // namespace ncsim::jerk

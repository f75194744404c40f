// jerk/reach.cpp: the inverse of the velocity change: the highest velocity reachable within a
// distance (a planner's forward pass) and the highest entry velocity from which an exit
// velocity is reachable (its backward pass). See jerk.hpp.
//
// Method (forward motion, v0 >= 0): the change (v0, a0) -> (v1, 0) with v1 above
// v_zero = v0 + a0|a0|/(2J) is a positive pulse; with x = a_peak / J and b = a0 / J its
// distance is the cubic
//     d(x) = J x^3 + (2 v0 - J b^2) x - v0 b + J b^3 / 3,   v1 = v0 + J x^2 - a0^2 / (2J),
// while the peak stays below the limit A (x <= A/J), and beyond it the hold adds a velocity w
// with  w^2 + 2 w (v_a + A^2/J) = 2 A (s - d(A/J))  (v_a: velocity after phase 1), a quadratic
// solved in closed form. The cubic is increasing and convex on the domain, so Newton's method
// started above the root descends monotonically onto it (guaranteed convergence, no overshoot).

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/tolerance.hpp"
#include "jerk/jerk.hpp"

namespace ncsim::jerk {

namespace {

// Distance of the positive pulse with peak x = a_peak / J (see the file header).
double cubic_distance(double x, double v0, double b, double j) noexcept {
  return j * x * x * x + (2.0 * v0 - j * b * b) * x - v0 * b + j * b * b * b / 3.0;
}

// Highest v1 of the positive pulse from (v0, a0 <= A) whose distance is s (A: a_lim).
double positive_pulse(double v0, double a0, double s, double a_lim, double j) noexcept {
  const double b = a0 / j;
  const double x_hi = a_lim / j;
  // The cubic is increasing from max(b, 0), or from its minimum when a start moving backward
  // makes it dip first (outside the documented domain; kept total and monotone).
  const double p1 = 2.0 * v0 - j * b * b;
  double x_lo = std::max(b, 0.0);
  if (p1 < 0.0) x_lo = std::max(x_lo, std::sqrt(-p1 / (3.0 * j)));
  x_lo = std::min(x_lo, x_hi);
  const auto v_of = [&](double x) { return v0 + j * x * x - a0 * a0 / (2.0 * j); };
  if (s <= cubic_distance(x_lo, v0, b, j)) return v_of(x_lo);
  const double d_hi = cubic_distance(x_hi, v0, b, j);
  if (s >= d_hi) {
    // The peak reaches A: a hold gains w on top of the no-hold velocity v_of(x_hi).
    const double t1 = x_hi - b;
    const double v_a = v0 + a0 * t1 + 0.5 * j * t1 * t1;
    const double beta = v_a + a_lim * x_hi;
    const double r2 = 2.0 * a_lim * (s - d_hi);
    const double root = std::sqrt(beta * beta + r2);
    const double w = beta >= 0.0 ? r2 / (beta + root) : root - beta;
    return v_of(x_hi) + w;
  }
  // Newton from an upper bound of the root: J x^3 + p1 x + q0 = s with q0 the constant term.
  const double q0 = -v0 * b + j * b * b * b / 3.0;
  double x = x_hi;
  if (p1 >= 0.0) {
    // Two upper bounds of the root besides x_hi: cube = cbrt(c), c = (s - q0) / J (drop p1 x >= 0)
    // and, when p1 > 0, lin = (s - q0) / p1 (drop J x^3); the start is max(min(x_hi, cube, lin),
    // x_lo). The cube root is the costly one and mostly not the smallest: with m = min(x_hi, lin),
    // when c is a normal double and m^3 lies below c by a relative kRelTol (far beyond the rounding
    // of m^3 and of cbrt, a few ulp), cube > m and the start is max(m, x_lo) without it: the same
    // bits (issue 12, session 26: 20 million random cases, none differs).
    const double c = std::max(0.0, s - q0) / j;
    const double lin = p1 > 0.0 ? (s - q0) / p1 : x_hi;
    const double m = std::min(x_hi, lin);
    if (c >= std::numeric_limits<double>::min() && m * m * m < c * (1.0 - kRelTol)) {
      x = std::max(m, x_lo);
    } else {
      x = std::max(std::min(x, std::cbrt(c)), x_lo);
      if (p1 > 0.0) x = std::max(std::min(x, lin), x_lo);
    }
  }
  for (int i = 0; i < 200; ++i) {
    const double f = cubic_distance(x, v0, b, j) - s;
    if (!(f > 0.0)) break;
    const double slope = 3.0 * j * x * x + p1;
    if (!(slope > 0.0)) break;
    const double x_next = std::max(x - f / slope, x_lo);
    if (!(x_next < x)) break;
    x = x_next;
  }
  return v_of(x);
}

}  // namespace

double reachable_velocity(double v0, double a0, double s, double a_lim, double j) noexcept {
  if (a0 > a_lim) {
    // Acceleration beyond the limit: back to it with j first (limits first); the rest is a
    // positive pulse (or shorter than this phase: then v_zero, see below).
    const double t = (a0 - a_lim) / j;
    const State st = advance(State{0.0, v0, a0}, -j, t);
    if (s >= st.p) return positive_pulse(st.v, a_lim, s - st.p, a_lim, j);
  }
  // Below the distance of releasing the start acceleration (a -> 0 with j) no change ends
  // with a = 0: the answer is then that release's velocity v_zero (positive_pulse's x_lo).
  if (a0 > a_lim) return v0 + a0 * a0 / (2.0 * j);
  return positive_pulse(v0, a0, s, a_lim, j);
}

double entry_velocity_for_exit(double v_exit, double s, double d_max, double j) noexcept {
  // Time reversal: slowing from v_entry to v_exit over s is the speed-up from v_exit over s.
  return reachable_velocity(v_exit, 0.0, std::max(s, 0.0), d_max, j);
}

}  // namespace ncsim::jerk

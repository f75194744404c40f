#pragma once
// jerk/root: the bracketed root solver of the level searches (jerk/move.cpp, jerk/reverse.cpp).
//
// Purpose: the highest feasible parameter x of a move (a cruise level, a turning level) is the
// root of an increasing g(x) = covered distance - D; feasible is g <= 0 (the rest of the way
// is then a cruise). Input: a bracket x_neg (g <= 0), x_pos (g > 0), the slopes g' at both
// ends (NaN where unknown), a tolerance tol on g [mm], and gs(x, slope) evaluating g and its
// slope. Output: an x with -tol <= g(x) <= 0, or the last x_neg when the bracket has shrunk to
// rounding. Invariants: every step stays inside the bracket; nothing allocates or throws.
// Internal to jerk/ (not part of jerk.hpp).

#include <algorithm>
#include <cmath>
#include <limits>

#include "jerk/jerk.hpp"

namespace ncsim::jerk::detail {

// The step from one end (x0, g0 = g(x0), slope s0 > 0, curvature c0, NaN where unknown): the root
// of the local quadratic model g0 + s0 dx + c0 dx^2 / 2, aimed at g = -tol / 2, or the Newton
// step where the model has no root or no curvature is known (NaN c0: disc is NaN). The level
// searches also take it once from the top before their kink candidate (jerk/move.cpp
// top_level, jerk/reverse.cpp). Always inlined: as a plain inline function GCC 12 allocated
// the searches' registers differently, +0.6 instructions a fastest_move (callgrind, 20,000 draws);
// inlined the machine code of jerk/move.cpp is the one of the three written-out copies.
[[gnu::always_inline]] inline double curve_step(double x0, double g0, double s0, double c0,
                                                double tol) noexcept {
  const double r = g0 + 0.5 * tol;
  const double disc = s0 * s0 - 2.0 * c0 * r;
  return disc >= 0.0 ? x0 - 2.0 * r / (s0 + std::sqrt(disc)) : x0 - r / s0;
}

// A Newton step from the end nearer the root (aimed a little below it, at g = -tol / 2, so it
// lands on the feasible side) wherever it stays inside the bracket, else the regula falsi step
// (Anderson-Bjorck weight, bisection as a fallback). Without a slope, an end within tol above the
// root (where regula falsi would crawl from the far end) steps by the secant of the bracket. After
// three Newton steps in a row that shrank the bracket by less than 10 % a regula falsi step
// follows, so a poor slope costs steps, never convergence.
//
// With curvatures (solve_with_curve: c_neg, c_pos and gsc(x, slope, curve), NaN where unknown)
// the Newton step is the root of the local quadratic model g + s dx + c dx^2 / 2 (exact where g
// is a quadratic: the level search where both ramps hold at their limits), a Newton step where
// the model has no root or no curvature is known.
template <class G>
double solve_with_curve(double x_neg, double x_pos, double g_neg, double g_pos, double s_neg,
                        double s_pos, double c_neg, double c_pos, double tol, G gsc) noexcept {
  double w_neg = g_neg;  // the regula falsi's (weighted) end values
  double w_pos = g_pos;
  int side = 0;
  int slow = 0;  // Newton steps in a row that shrank the bracket by < 10 % (a poor slope)
  for (int i = 0; i < 200; ++i) {
    const double width = std::abs(x_pos - x_neg);
    if (width <= kResidue * std::max(std::abs(x_neg), std::abs(x_pos))) break;
    const double lo = std::min(x_neg, x_pos);
    const double hi = std::max(x_neg, x_pos);
    // Newton from either end (on a convex g both land at or above the root: the nearer one is
    // taken), aimed at g = -tol / 2.
    double x = hi;
    bool newton = false;
    const auto try_newton = [&](double x0, double g0, double s0, double c0) {
      if (!(s0 > 0.0)) return;
      const double xn = curve_step(x0, g0, s0, c0, tol);
      if (xn > lo && xn < hi && (!newton || std::abs(xn - x_neg) < std::abs(x - x_neg))) {
        x = xn;
        newton = true;
      }
    };
    if (slow < 3) {
      try_newton(x_neg, g_neg, s_neg, c_neg);
      const bool secant = std::isnan(s_pos) && g_pos <= tol;
      try_newton(x_pos, g_pos, secant ? (g_pos - g_neg) / (x_pos - x_neg) : s_pos,
                 secant ? std::numeric_limits<double>::quiet_NaN() : c_pos);
    }
    if (!newton) {
      x = (x_neg * w_pos - x_pos * w_neg) / (w_pos - w_neg);
      if (!(x > lo && x < hi)) x = 0.5 * (x_neg + x_pos);
    }
    double slope = 0.0;
    double curve = 0.0;
    const double gx = gsc(x, slope, curve);
    if (gx <= 0.0) {
      if (gx >= -tol) return x;
      if (!newton && side == -1) w_pos *= anderson_bjorck(gx, w_neg);
      x_neg = x;
      g_neg = w_neg = gx;
      s_neg = slope;
      c_neg = curve;
      side = newton ? 0 : -1;
    } else {
      if (!newton && side == 1) w_neg *= anderson_bjorck(gx, w_pos);
      x_pos = x;
      g_pos = w_pos = gx;
      s_pos = slope;
      c_pos = curve;
      side = newton ? 0 : 1;
    }
    slow = newton && std::abs(x_pos - x_neg) > 0.9 * width ? slow + 1 : 0;
  }
  return x_neg;
}

// The same without curvatures: gs(x, slope) (the steps are Newton steps).
template <class G>
double solve_with_slope(double x_neg, double x_pos, double g_neg, double g_pos, double s_neg,
                        double s_pos, double tol, G gs) noexcept {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return solve_with_curve(x_neg, x_pos, g_neg, g_pos, s_neg, s_pos, nan, nan, tol,
                          [&](double x, double& slope, double& curve) {
                            curve = nan;
                            return gs(x, slope);
                          });
}

}  // namespace ncsim::jerk::detail

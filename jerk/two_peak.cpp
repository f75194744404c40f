// jerk/two_peak.cpp: two-peak velocity changes (see jerk.hpp, "ptp additions").
//
// In the frame toward the target (velocities v0, v1 >= 0, distance D), let sigma be the
// direction of the velocity change beyond the start's release velocity
// v_zero = v0 + a0|a0|/(2J): sigma = +1 when v1 > v_zero (speeding up, limit A = A+), -1 when
// v1 < v_zero (braking, A = A-). With the start acceleration pointing the same way
// (alpha0 = sigma a0 > 0) the change can dip: jerk -sigma J from alpha0 down to x in
// [0, min(alpha0, A)], jerk +sigma J up to y, [hold at A], jerk -sigma J to 0. The velocity
// gain sigma (v1 - v0) = W / J fixes y from x:
//     y^2 = x^2 - alpha0^2 / 2 + W                              (y <= A, no hold), else
//     y = A, hold h = (2W - alpha0^2 + 2x^2 - 2A^2) / (2 J A).
// x = min(alpha0, A) is the direct ramp, x = 0 releases a0 first (the single-peak family's
// level v_zero); between them the distance d(x) moves monotonically from one to the other, and
// the root of d(x) = D is found by a bracketed regula falsi (Anderson-Bjorck). The dip does not
// cross 0, so the velocity is monotone between v0 and v1: A+ bounds a speeding change, A- a braking
// one.

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/tolerance.hpp"
#include "jerk/jerk.hpp"
#include "jerk/trusted.hpp"

namespace ncsim::jerk {

namespace {

// The change with dip x in the frame (start v0, a0); distance by the closed-form chain.
struct Shape {
  double sigma = 1.0;
  double alpha0 = 0.0;  // sigma a0 > 0
  double lim = 0.0;     // A+ or A-
  double w = 0.0;       // J sigma (v1 - v0) > alpha0^2 / 2
  double v0 = 0.0;
  double a0 = 0.0;
  double v1 = 0.0;
  double j = 0.0;
};

TwoPeak make(const Shape& s, double x) noexcept {
  TwoPeak tp;
  double y2 = x * x - 0.5 * s.alpha0 * s.alpha0 + s.w;
  double y = std::sqrt(std::max(0.0, y2));
  double h = 0.0;
  if (y > s.lim) {
    y = s.lim;
    const double num = 2.0 * s.w - s.alpha0 * s.alpha0 + 2.0 * x * x - 2.0 * s.lim * s.lim;
    h = std::max(0.0, num / (2.0 * s.j * s.lim));
  }
  y = std::max(y, x);
  const double down = s.alpha0 - x;  // first phase: alpha0 -> x
  const double up = y - x;
  tp.jerk = {-s.sigma * s.j, s.sigma * s.j, 0.0, -s.sigma * s.j};
  tp.duration = {down > kResidue * s.alpha0 ? down / s.j : 0.0, up > kResidue * y ? up / s.j : 0.0,
                 h, y / s.j};
  tp.a_end = {s.sigma * x, s.sigma * y, s.sigma * y, 0.0};
  tp.v_end = s.v1;
  return tp;
}

double chain_distance(const Shape& s, const TwoPeak& tp) noexcept {
  State st{0.0, s.v0, s.a0};
  for (std::size_t i = 0; i < 4; ++i) {
    st = advance(st, tp.jerk[i], tp.duration[i]);
    st.a = tp.a_end[i];
  }
  return st.p;
}

}  // namespace

Status two_peak_move(const State& start, double p1, double v1, const Limits& lim,
                     TwoPeak& out) noexcept {
  if (!valid(lim) || !std::isfinite(start.p) || !std::isfinite(start.v) ||
      !std::isfinite(start.a) || !std::isfinite(p1) || !std::isfinite(v1) ||
      std::abs(v1) > lim.v_max) {
    return Status::invalid_input;
  }
  return detail::two_peak_move_trusted(start, p1, v1, lim, out);
}

namespace {

// The change's frame toward the target (sign f, distance d) and its Shape but for w; false where
// no two-peak change applies (no distance, a target behind the arrival, no dip: a single ramp).
bool shape_of(const State& start, double p1, double v1, const Limits& lim, Shape& s, double& f,
              double& d) noexcept {
  const double dp = p1 - start.p;
  if (!(dp != 0.0)) return false;
  f = dp > 0.0 ? 1.0 : -1.0;
  s.v0 = f * start.v;
  s.a0 = f * start.a;
  s.v1 = f * v1;
  s.j = lim.j_max;
  d = f * dp;
  if (s.v1 < 0.0 || std::abs(s.v0) > lim.v_max) return false;
  const double v_zero = s.v0 + s.a0 * std::abs(s.a0) / (2.0 * s.j);
  if (s.v1 == v_zero) return false;
  s.sigma = s.v1 > v_zero ? 1.0 : -1.0;
  s.alpha0 = s.sigma * s.a0;
  if (!(s.alpha0 > 0.0)) return false;  // no dip: a single ramp
  s.lim = s.sigma > 0.0 ? lim.a_max : lim.d_max;
  if (s.v0 < 0.0) {
    // Speeding up from a start moving backward: the acceleration slows the motion until v = 0
    // (A-) and speeds it up after (A+); the peaks stay within both, and so must the start.
    s.lim = std::min(lim.a_max, lim.d_max);
    if (s.sigma < 0.0 || s.alpha0 > s.lim) return false;
  }
  return true;
}

}  // namespace

bool detail::two_peak_applies(const State& start, double p1, double v1,
                              const Limits& lim) noexcept {
  Shape s;
  double f = 0.0;
  double d = 0.0;
  return shape_of(start, p1, v1, lim, s, f, d);
}

Status detail::two_peak_move_trusted(const State& start, double p1, double v1, const Limits& lim,
                                     TwoPeak& out) noexcept {
  Shape s;
  double f = 1.0;
  double d = 0.0;
  if (!shape_of(start, p1, v1, lim, s, f, d)) return Status::not_supported;
  s.w = s.j * s.sigma * (s.v1 - s.v0);
  const double x_hi = std::min(s.alpha0, s.lim);
  const auto g = [&](double x) { return chain_distance(s, make(s, x)) - d; };
  double g_lo = g(0.0);
  double g_hi = g(x_hi);
  if (!(g_lo * g_hi < 0.0)) return Status::not_supported;  // D outside (d(0), d(x_hi))
  // Regula falsi (Anderson-Bjorck weight) on x in [0, x_hi] (bisection fallback); g changes sign in
  // between.
  double lo = 0.0;
  double hi = x_hi;
  int side = 0;
  const double tol = kResidue * d;
  for (int i = 0; i < 200 && hi - lo > kBisectWidth * hi; ++i) {
    double x = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    const double gx = g(x);
    if (std::abs(gx) <= tol) {
      lo = hi = x;
      break;
    }
    if ((gx < 0.0) == (g_lo < 0.0)) {
      if (side == -1) g_hi *= detail::anderson_bjorck(gx, g_lo);
      lo = x;
      g_lo = gx;
      side = -1;
    } else {
      if (side == 1) g_lo *= detail::anderson_bjorck(gx, g_hi);
      hi = x;
      g_hi = gx;
      side = 1;
    }
  }
  // The end whose distance is short of D (the rest of rounding size is met by the caller's
  // exact end state).
  const double x = (g_lo <= 0.0) ? lo : hi;
  out = make(s, x);
  out.sign = f;
  return Status::ok;
}

State end_state(const State& start, const TwoPeak& tp) noexcept {
  const double s = tp.sign;
  State st{s * start.p, s * start.v, s * start.a};
  for (std::size_t i = 0; i < 4; ++i) {
    st = advance(st, tp.jerk[i], tp.duration[i]);
    st.a = tp.a_end[i];
  }
  st.v = tp.v_end;
  return State{s * st.p, s * st.v, s * st.a};
}

}  // namespace ncsim::jerk

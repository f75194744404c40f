// jerk/move.cpp: single-peak moves (change to a level, cruise, change to the end velocity) of
// minimum or of a prescribed duration (see jerk.hpp).
//
// In the frame of travel (D = |p1 - p0| >= 0) a level vm in [0, V] gives
//     dist(vm) = distance of (v0, a0) -> (vm, 0) + distance of (vm, 0) -> (v1, 0),
//     T(vm)    = ramp times + (D - dist(vm)) / vm          (needs dist(vm) <= D).
// The minimum of the family is at the highest feasible level: V when dist(V) <= D, else a
// root of dist(vm) = D, bracketed by dist(0) <= D < dist(V). T(vm) is continuous and grows
// without bound as vm -> 0 when dist(0) < D, so every longer duration has a level in
// (0, vm_top]; both roots are found by a bracketed regula falsi (Anderson-Bjorck) (guaranteed: the
// bracket shrinks every step, with bisection as a fallback). When dist(0) == D the move can dwell
// at rest between the ramps, which takes up any remaining time.

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>

#include "core/tolerance.hpp"
#include "jerk/crossing.hpp"
#include "jerk/jerk.hpp"
#include "jerk/root.hpp"
#include "jerk/trusted.hpp"

namespace ncsim::jerk {

namespace {

// The move in its frame: start (v0, a0), end velocity v1 >= 0, distance d >= 0.
struct Frame {
  double sign = 1.0;
  double v0 = 0.0;
  double a0 = 0.0;
  double v1 = 0.0;
  double d = 0.0;
  double v_zero = 0.0;       // release velocity v0 + a0 |a0| / (2J): where ramp 1 vanishes
  detail::CrossingStart cs;  // the start's part of a crossing through v = 0 (jerk/crossing.hpp)
};

// The natural frame: toward the target, else the direction of arrival or of motion.
double natural_sign(const State& start, double p1, double v1) noexcept {
  const double dp = p1 - start.p;
  if (dp != 0.0) return dp > 0.0 ? 1.0 : -1.0;
  if (v1 != 0.0) return v1 > 0.0 ? 1.0 : -1.0;
  if (start.v != 0.0) return start.v > 0.0 ? 1.0 : -1.0;
  return 1.0;
}

// The release velocity of a frame start (v0, a0): v0 + a0 |a0| / (2J).
double release_velocity(double v0, double a0, const Limits& lim) noexcept {
  return v0 + a0 * std::abs(a0) / (2.0 * lim.j_max);
}

// Frame with the given sign; its distance d is negative when the target lies behind (a move
// that overshoots and comes back at a level vm >= 0 in this frame). `v_zero`: the frame start's
// release velocity (release_velocity of its v0, a0).
Frame frame_of(const State& start, double p1, double v1, double sign, double v_zero,
               const Limits& lim) noexcept {
  Frame f{sign, sign * start.v, sign * start.a, sign * v1, sign * (p1 - start.p), v_zero, {}};
  if (f.v0 < 0.0 || f.a0 < 0.0) detail::crossing_start_into(f.cs, f.v0, f.a0, v_zero, lim, true);
  return f;
}

Frame frame_of(const State& start, double p1, double v1, double sign, const Limits& lim) noexcept {
  return frame_of(start, p1, v1, sign, release_velocity(sign * start.v, sign * start.a, lim), lim);
}

Frame frame_of(const State& start, double p1, double v1, const Limits& lim) noexcept {
  return frame_of(start, p1, v1, natural_sign(start, p1, v1), lim);
}

struct Level {
  Crossing cross;
  Ramp first;
  Ramp second;
  double dist = 0.0;    // distance of all ramps [mm]
  double path = 0.0;    // sum of the ramps' |distances| [mm]: the scale of dist's rounding
  double t_ramp = 0.0;  // time of all ramps [s]
  double slope = std::numeric_limits<double>::quiet_NaN();  // d dist / d vm [s], level_slope
  double curve = std::numeric_limits<double>::quiet_NaN();  // d2 dist / d vm2 [s^2/mm]
};

// d dist / d vm of a level [s]. A ramp from a fixed start ending at vm with signed peak a_p
// covers a distance whose derivative in vm is vm / a_p + |a_p| / (2J) (with a hold at the
// limit as well: then the hold's length is what changes); the second ramp, read backward in
// time (the same distance), is a ramp ending at vm with peak -a_p. A crossing through v = 0 is
// fixed unless its a_zero is sqrt(2 J vm) (then the first ramp only releases it and both move
// with vm). NaN there and where a ramp vanishes (the distance has a kink with an infinite slope).
//
// Its curvature (the level classifier: which ramps hold at their limit): a ramp's term is
// T(p) = vm / p + |p| / (2J) with p = p1, or p = -p2 for the second ramp; a ramp holding at its
// limit keeps p (dT/dvm = 1 / p), one without a hold has 2 p^2 = 2J |vm - v_other| + const, so
// dp/dvm = J / (2 |p|) and dT/dvm = 1/p + p' (sgn(p) / (2J) - vm / p^2). Where both ramps hold,
// dist is a quadratic in vm and the solver's quadratic step lands on the root at once.
void level_slope(Level& lv, double vm, double j) noexcept {
  const double p1 = lv.first.a_peak;
  const double q = -lv.second.a_peak;
  const bool cross_fixed =
      !(lv.cross.time() > 0.0) || lv.cross.a_zero < (1.0 - kRelTol) * std::sqrt(2.0 * j * vm);
  if (!cross_fixed || p1 == 0.0 || q == 0.0) {
    lv.slope = lv.curve = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  const double a1 = std::abs(p1);
  const double aq = std::abs(q);
  lv.slope = vm / p1 + vm / q + (a1 + aq) / (2.0 * j);
  const double half = 0.5 / j;  // (-0.5) / j is -half to the bit: one division for both ramps
  const auto curve_of = [&](double p, double ap, bool hold) {
    const double dp = hold ? 0.0 : j / (2.0 * ap);
    return 1.0 / p + dp * ((p > 0.0 ? half : -half) - vm / (p * p));
  };
  lv.curve =
      curve_of(p1, a1, lv.first.duration[1] > 0.0) + curve_of(q, aq, lv.second.duration[1] > 0.0);
}

// velocity_ramp(vm, 0, v1, a_up, a_down, j) for a ramp that starts at a = 0 (a level's second
// ramp): the same expressions with a0 = 0 written out, so the same phases bit for bit
// (v_zero = vm, no start acceleration beyond a limit, radicand J dv), without the terms the
// compiler cannot drop for a literal 0 (a0 |a0| / (2J) is a division; IEEE signed zeros keep
// the products): issue 11, session 25.
Ramp ramp_from_coast(double vm, double v1, double a_up, double a_down, double j) noexcept {
  Ramp out;
  out.v_end = v1;
  const double s = v1 >= vm ? 1.0 : -1.0;
  const double a_lim = s > 0.0 ? a_up : a_down;
  const double dv = s * (v1 - vm);
  const double radicand = j * dv;
  double a_peak = radicand > kResidue * std::abs(radicand) ? std::sqrt(radicand) : 0.0;
  double t_hold = 0.0;
  if (a_peak > a_lim) {
    a_peak = a_lim;
    const double dv_ramps = (2.0 * a_peak * a_peak) / (2.0 * j);  // [mm/s]
    const double dv_hold = dv - dv_ramps;
    if (dv_hold > kResidue * (std::abs(dv) + std::abs(dv_ramps))) t_hold = dv_hold / a_peak;
  }
  out.jerk = {s * j, 0.0, -s * j};
  out.duration = {a_peak > kResidue * a_peak ? a_peak / j : 0.0, t_hold, a_peak / j};
  out.a_peak = s * a_peak;
  return out;
}

// The first part of a level, (v0, a0) -> (vm, 0), into `cross` and `first`; returns its
// distance [mm] and adds its way (the pieces' |distances|) to `path`.
double first_part(const Frame& f, double vm, const Limits& lim, Crossing& cross, Ramp& first,
                  double& path) noexcept {
  cross = Crossing{};
  // A first ramp from a frame velocity below 0 slows down (A-) until v = 0 and speeds up (A+)
  // after it: the crossing ramp switches the limit at v = 0. Where it does not apply (a start
  // acceleration beyond A- or one forcing more than min(A+, A-) at v = 0), one ramp under the
  // smaller limit.
  // (The start's part of the crossing is prepared once per frame: frame_of.)
  double d_cross = 0.0;
  if ((f.v0 < 0.0 || f.a0 < 0.0) && vm > 0.0 &&
      detail::crossing_from(f.cs, vm, lim, cross, first, &d_cross)) {
    const double d_first = distance(0.0, cross.a_zero, first);
    path += std::abs(d_cross) + std::abs(d_first);
    return d_cross + d_first;
  }
  // (A stop from v0 < 0 only slows down: A-.)
  const double a_up =
      f.v0 < 0.0 ? (vm > 0.0 ? std::min(lim.a_max, lim.d_max) : lim.d_max) : lim.a_max;
  first = detail::velocity_ramp_released(f.v0, f.a0, f.v_zero, vm, a_up, lim.d_max, lim.j_max);
  const double d_first = distance(f.v0, f.a0, first);
  path += std::abs(d_first);
  return d_first;
}

// Evaluates the level vm into `out` (every member but slope and curve written: the root
// searches evaluate many levels into one Level without constructing and copying a new one each
// time, and take level_slope only where their solver steps from the level).
void level_into(const Frame& f, double vm, const Limits& lim, Level& out) noexcept {
  out.second = ramp_from_coast(vm, f.v1, lim.a_max, lim.d_max, lim.j_max);
  // (vm, 0) -> (v1, 0) from a = 0 is symmetric in time: the mean velocity is (vm + v1) / 2.
  const double t_second = out.second.time();
  out.dist = 0.5 * (vm + f.v1) * t_second;
  out.path = std::abs(out.dist);
  out.dist += first_part(f, vm, lim, out.cross, out.first, out.path);
  out.t_ramp = out.cross.time() + out.first.time() + t_second;
}

// dist(vm) - D at a candidate of top_level that is a kink (vm = v_zero or vm = v1: one of the
// two ramps vanishes there), without the Level: the vanishing ramp is not built, the release
// of a0 (vm = v_zero in a frame without a crossing: one phase of jerk -sgn(a0) J for |a0|/J,
// v0 t + a0 t^2/2 - |a0| J t^3/6 sgn(a0) = v0 t + a0 t^2/3) in closed form, and neither the
// ramps' times nor the slope are needed (the slope does not exist at a kink). The same
// distance as level_into's to rounding (issue 11, eighth round: the candidates are 0.75 of the
// 3.1 level evaluations per plan).
double kink_gap(const Frame& f, double vm, double v_zero, const Limits& lim) noexcept {
  const double j = lim.j_max;
  double dist = 0.0;
  if (vm != f.v1) {
    // (vm, 0) -> (v1, 0) from a = 0 is symmetric in time: the mean velocity is (vm + v1) / 2.
    dist = 0.5 * (vm + f.v1) * ramp_from_coast(vm, f.v1, lim.a_max, lim.d_max, j).time();
  }
  if (vm == v_zero && !f.cs.possible) {
    const double t = std::abs(f.a0) / j;
    return dist + t * (f.v0 + f.a0 * t * (1.0 / 3.0)) - f.d;
  }
  Crossing cross;
  Ramp first;
  double path = 0.0;
  return dist + first_part(f, vm, lim, cross, first, path) - f.d;
}

Level level(const Frame& f, double vm, const Limits& lim) noexcept {
  Level out;
  level_into(f, vm, lim, out);
  return out;
}

// Root of g between x_neg (g <= 0) and x_pos (g > 0), in either order (regula falsi with the
// Anderson-Bjorck weight, bisection as a fallback); returns the final x_neg, where g <= 0.
template <class G>
double solve_bracket(double x_neg, double x_pos, double g_neg, double g_pos, double tol,
                     G g) noexcept {
  int side = 0;
  for (int i = 0; i < 200; ++i) {
    if (std::abs(x_pos - x_neg) <= kResidue * std::max(std::abs(x_neg), std::abs(x_pos))) break;
    double x = (x_neg * g_pos - x_pos * g_neg) / (g_pos - g_neg);
    if (!(x > std::min(x_neg, x_pos) && x < std::max(x_neg, x_pos))) x = 0.5 * (x_neg + x_pos);
    const double gx = g(x);
    if (gx <= 0.0) {
      if (gx >= -tol) return x;
      if (side == -1) g_pos *= detail::anderson_bjorck(gx, g_neg);
      x_neg = x;
      g_neg = gx;
      side = -1;
    } else {
      if (side == 1) g_neg *= detail::anderson_bjorck(gx, g_pos);
      x_pos = x;
      g_pos = gx;
      side = 1;
    }
  }
  return x_neg;
}

// Highest feasible level; negative when no level in [0, V] fits. dist(vm) is not monotone:
// it dips where a ramp vanishes (vm = v_zero of the start, vm = v1), so the feasible levels need
// not be one interval. The candidates V, max(v_zero, v1), min(v_zero, v1), 0 (clamped to [0, V])
// are tried from the top; between the first feasible one and the next higher one both ramps grow
// with vm, and the root of dist(vm) = D there is the highest feasible level.
// `out` receives the Level of the answer (evaluated once: the caller needs its ramps).
// `curved`: the solver's steps use the level's curvature (false: Newton steps only, the oracle
// of level_curve_test.cpp).
double top_level(const Frame& f, const Limits& lim, Level& out, bool curved = true) noexcept {
  // The last level evaluated is kept: the root solver usually returns it.
  double last_vm = -1.0;
  const auto g = [&](double vm) {
    level_into(f, vm, lim, out);
    last_vm = vm;
    return out.dist - f.d;
  };
  const auto answer = [&](double vm) {
    if (vm != last_vm) level_into(f, vm, lim, out);
    return vm;
  };
  const double no_curve = std::numeric_limits<double>::quiet_NaN();
  const double g_top = g(lim.v_max);
  if (g_top <= 0.0) return lim.v_max;
  level_slope(out, lim.v_max, lim.j_max);
  double s_hi = out.slope;
  double c_hi = curved ? out.curve : no_curve;
  // Rounding of dist grows with the way the ramps travel (a detour much longer than D).
  const double tol = kResidue * std::max(std::abs(f.d), out.path);  // out: the level at V
  // (The slope only where the solver goes on from the level: not at the root it returns.)
  const auto gsc = [&](double vm, double& slope, double& curve) {
    const double gv = g(vm);
    slope = curve = no_curve;
    if (gv <= 0.0 && gv >= -tol) return gv;
    level_slope(out, vm, lim.j_max);
    slope = out.slope;
    curve = curved ? out.curve : no_curve;
    return gv;
  };
  const auto clamp = [&](double v) { return std::clamp(v, 0.0, lim.v_max); };
  const double v_zero = f.v_zero;  // ramp 1 vanishes
  const std::array<double, 3> below{clamp(std::max(v_zero, f.v1)), clamp(std::min(v_zero, f.v1)),
                                    0.0};
  double hi = lim.v_max;
  double g_hi = g_top;
  // The root step from V before the candidates (issue 11, session 25). The first candidate
  // below V, c, bounds the piece where both ramps grow with vm (g rises on (c, V]); where c is a
  // kink (no slope there) the solver's first step in [c, V] is this step from V alone, so where
  // it lands in (c, V) it is taken before c is evaluated: a level in tolerance there is the
  // root of that piece, the highest feasible level, and c is not needed (in 55 % of the
  // searches: the step is exact where both ramps hold at their limits). Otherwise the step
  // narrows the bracket: feasible, the root lies in [x, V]; infeasible, x is the new top.
  const auto top_c = std::find_if(below.begin(), below.end(), [&](double c) { return c < hi; });
  if (top_c != below.end() && (*top_c == v_zero || *top_c == f.v1) && s_hi > 0.0) {
    const double x = detail::curve_step(hi, g_top, s_hi, c_hi, tol);
    if (x > *top_c && x < hi) {
      double s_x = no_curve;
      double c_x = no_curve;
      const double g_x = gsc(x, s_x, c_x);
      if (g_x <= 0.0) {
        if (g_x >= -tol) return x;  // `out` holds the level at x
        return answer(detail::solve_with_curve(x, hi, g_x, g_hi, s_x, s_hi, c_x, c_hi, tol, gsc));
      }
      hi = x;
      g_hi = g_x;
      s_hi = s_x;
      c_hi = c_x;
    }
  }
  for (const double c : below) {
    if (!(c < hi)) continue;
    // A kink candidate's distance without a level evaluation (no slope there: NaN).
    const bool kink = c == v_zero || c == f.v1;
    const double g_c = kink ? kink_gap(f, c, v_zero, lim) : g(c);
    if (!kink) level_slope(out, c, lim.j_max);
    const double s_c = kink ? no_curve : out.slope;
    const double c_c = kink || !curved ? no_curve : out.curve;
    if (g_c <= 0.0) {
      return answer(detail::solve_with_curve(c, hi, g_c, g_hi, s_c, s_hi, c_c, c_hi, tol, gsc));
    }
    hi = c;
    g_hi = g_c;
    s_hi = s_c;
    c_hi = c_c;
  }
  return -1.0;
}

// A feasible level for stretching a move in time: a root of dist(vm) = D bracketed from 0
// (dist(0) <= D), so that lowering the level from it toward 0 stays feasible in the common
// case; negative when dist(0) > D. move_of_duration checks the level it finally uses.
double stretch_level(const Frame& f, const Limits& lim) noexcept {
  const double d_top = level(f, lim.v_max, lim).dist;
  if (d_top <= f.d) return lim.v_max;
  const double d_zero = level(f, 0.0, lim).dist;
  if (d_zero > f.d) return -1.0;
  return solve_bracket(0.0, lim.v_max, d_zero - f.d, d_top - f.d, kResidue * std::abs(f.d),
                       [&](double vm) { return level(f, vm, lim).dist - f.d; });
}

double cruise_time(const Frame& f, double vm, const Level& lv) noexcept {
  // A rest within the rounding of the ramps' distances is no cruise: at a low level it would
  // turn a rounding residue into time (docs/axes-profile.md, "Numerics").
  const double rest = f.d - lv.dist;
  if (!(vm > 0.0) || rest <= kResidue * std::max(std::abs(f.d), lv.path)) return 0.0;
  return rest / vm;
}

bool finite(const State& s) noexcept {
  return std::isfinite(s.p) && std::isfinite(s.v) && std::isfinite(s.a);
}

// Writes every member of `m` (in place: no Move zero-filled and copied per answer).
void set_move(Move& m, const Frame& f, double vm, const Level& lv, double t_cruise) noexcept {
  m.sign = f.sign;
  m.cross = lv.cross;
  m.first = lv.first;
  m.second = lv.second;
  m.v_level = vm;
  m.t_cruise = t_cruise;
}

}  // namespace

bool crossing_ramp(double v0, double a0, double v1, const Limits& lim, Crossing& cross,
                   Ramp& rest) noexcept {
  // Before v = 0 the acceleration is bounded by c = A-, after it by e = A+; at v = 0 it must
  // lie within both. The fastest change keeps the acceleration as high as the bounds allow
  // (the upper envelope of the reachable accelerations), so it reaches v = 0 with
  //     a_z = min(A-, A+, sqrt(2 J v1), sqrt(a0^2 + 2 J |v0|))
  // (the last two: no overshoot of v1 after v = 0; the highest acceleration the remaining
  // velocity gain |v0| can build from a0). Before v = 0: jerk up to a_p, [hold at A-], jerk to
  // a_z, with the gain (2 a_p^2 - a0^2 - a_z^2) / (2J) [+ hold] = |v0|.
  // A forward start whose acceleration reverses the motion (v_zero < 0) crosses v = 0 twice;
  // the same phases apply (the jerk-up from a0 < 0 passes a = 0 at v = v_zero < 0).
  // (The expressions live in jerk/crossing.hpp, split by what depends on the start only.)
  return detail::crossing_from(detail::crossing_start(v0, a0, lim, false), v1, lim, cross, rest,
                               nullptr);
}

double min_single_peak_time(const State& start, double p1, double v1, const Limits& lim) noexcept {
  if (!valid(lim) || !finite(start) || !std::isfinite(p1) || !std::isfinite(v1)) return -1.0;
  const Frame f = frame_of(start, p1, v1, lim);
  if (f.v1 < 0.0 || f.v1 > lim.v_max) return -1.0;
  const double vm = stretch_level(f, lim);
  if (vm < 0.0) return -1.0;
  const Level lv = level(f, vm, lim);
  return lv.t_ramp + cruise_time(f, vm, lv);
}

namespace {

// move_of_duration in one frame (its distance f.d may be negative: the reversed frame of an
// overshoot, whose levels are the return velocity toward the target).
// The level is lowered from vm_top (feasible: dist(vm_top) <= D) through the range below it.
Status stretch_from(const Frame& f, double vm_top, double duration, const Limits& lim,
                    Move& out) noexcept {
  const double d_abs = std::abs(f.d);
  const Level top = level(f, vm_top, lim);
  const double t_min = top.t_ramp + cruise_time(f, vm_top, top);
  if (duration <= t_min) {
    if (duration < t_min * (1.0 - kRelRounding)) return Status::too_short;
    set_move(out, f, vm_top, top, cruise_time(f, vm_top, top));
    return Status::ok;
  }
  // Lowest level of the feasible range below vm_top: 0 when the move can stop and go within
  // the distance, else the root of dist(vm) = D below vm_top (cruise 0 there).
  const Level rest = level(f, 0.0, lim);
  const auto g_dist = [&](double vm) { return level(f, vm, lim).dist - f.d; };
  const bool dwell = std::abs(rest.dist - f.d) <= kResidue * std::max(d_abs, std::abs(rest.dist));
  double vm_low = 0.0;
  if (rest.dist > f.d && !dwell) {
    vm_low = solve_bracket(vm_top, 0.0, g_dist(vm_top), rest.dist - f.d, kResidue * d_abs, g_dist);
  }
  if (vm_low == 0.0 && dwell && duration >= rest.t_ramp) {
    set_move(out, f, 0.0, rest, duration - rest.t_ramp);  // dwell at rest in between
    return Status::ok;
  }
  // g(vm) = T(vm) - duration: <= 0 at vm_top, > 0 at the slow end of the range.
  const auto g = [&](double vm) {
    const Level lv = level(f, vm, lim);
    if (!(vm > 0.0)) return dwell ? lv.t_ramp - duration : std::numeric_limits<double>::max();
    return lv.t_ramp + std::max(0.0, f.d - lv.dist) / vm - duration;
  };
  double lo = vm_low;
  double g_lo = g(lo);
  if (vm_low == 0.0 && !dwell) {
    lo = vm_top;  // T grows without bound as vm -> 0: halve until too slow
    do {
      lo *= 0.5;
      g_lo = g(lo);
    } while (g_lo <= 0.0 && lo > 0.0);
  }
  if (!(g_lo > 0.0)) return Status::not_supported;  // slower than the family allows
  const double vm = solve_bracket(vm_top, lo, g(vm_top), g_lo, kResidue * duration, g);
  const Level lv = level(f, vm, lim);
  if (lv.dist > f.d + kRelTol * d_abs) return Status::not_supported;  // range not connected
  set_move(out, f, vm, lv, cruise_time(f, vm, lv));
  return Status::ok;
}

// The fallback of stretch_in_frame (issue 11, late round): the feasible levels below vm_top
// (dist(vm) <= D) can form several intervals, because dist dips where a ramp vanishes (vm =
// v_zero, vm = v1) and need not be monotone between; each interval has its own range of
// durations, and the two stretches above see only the interval of vm_top and the one reached
// from 0 (a root near vm_top can end a range faster than the duration while a lower interval
// takes it: NC5015 at the axis, sporadic near the start of a range). The levels are sampled on
// a grid of kScan steps with the dips v_zero and v1 added; every run of feasible samples is
// taken as an interval whose ends are refined to roots of dist(vm) = D (the feasible side), and
// the first interval whose durations enclose the prescribed one gives its level. A hole
// narrower than the grid between two feasible samples shows as an infeasible level found
// there: it is added as a sample, which splits the run, and the scan starts again (at most
// kSplits times).
Status stretch_scan(const Frame& f, double vm_top, double duration, const Limits& lim,
                    Move& out) noexcept {
  constexpr int kScan = 16;
  constexpr int kSplits = 8;
  constexpr int kCap = kScan + 3 + kSplits;
  const double d_abs = std::abs(f.d);
  const double tol_d = kResidue * d_abs;
  std::array<double, kCap> x{};   // sampled levels, descending [mm/s]
  std::array<double, kCap> gd{};  // dist(x) - D [mm]
  int n = 0;
  for (int k = kScan; k >= 0; --k)
    x[static_cast<std::size_t>(n++)] = vm_top * k / kScan;
  const double v_zero = f.v_zero;
  for (const double kink : {v_zero, f.v1}) {
    if (kink > 0.0 && kink < vm_top) x[static_cast<std::size_t>(n++)] = kink;
  }
  std::sort(x.begin(), x.begin() + n, std::greater<>());
  const auto g_dist = [&](double vm) { return level(f, vm, lim).dist - f.d; };
  Level lv;
  for (int i = 0; i < n; ++i) {
    level_into(f, x[static_cast<std::size_t>(i)], lim, lv);
    gd[static_cast<std::size_t>(i)] = lv.dist - f.d;
  }
  gd[0] = std::min(gd[0], 0.0);  // vm_top is feasible (top_level / stretch_level)
  const Level rest = level(f, 0.0, lim);
  const bool dwell = std::abs(rest.dist - f.d) <= kResidue * std::max(d_abs, std::abs(rest.dist));
  // g(vm) = T(vm) - duration on a feasible level (the dwell at vm = 0 when stop-and-go fills D).
  const auto g = [&](double vm) {
    const Level l = level(f, vm, lim);
    if (!(vm > 0.0)) return dwell ? l.t_ramp - duration : std::numeric_limits<double>::max();
    return l.t_ramp + std::max(0.0, f.d - l.dist) / vm - duration;
  };
  const auto at = [&](int k) { return x[static_cast<std::size_t>(k)]; };
  const auto g_at = [&](int k) { return gd[static_cast<std::size_t>(k)]; };
  const auto feasible = [&](int k) { return g_at(k) <= 0.0 || (at(k) == 0.0 && dwell); };
  for (int split = 0; split <= kSplits; ++split) {
    double hole = -1.0;  // an infeasible level found inside a run
    for (int i = 0; i < n && hole < 0.0;) {
      if (!feasible(i)) {
        ++i;
        continue;
      }
      int j = i;  // the run of feasible samples i..j (descending levels)
      while (j + 1 < n && feasible(j + 1))
        ++j;
      const double hi =
          i == 0 ? at(0) : solve_bracket(at(i), at(i - 1), g_at(i), g_at(i - 1), tol_d, g_dist);
      const double g_hi = g(hi);
      double lo = at(j);
      if (at(j) > 0.0 && j + 1 < n) {
        lo = solve_bracket(at(j), at(j + 1), g_at(j), g_at(j + 1), tol_d, g_dist);
      }
      double g_lo = g(lo);
      if (lo == 0.0 && dwell && duration >= rest.t_ramp && g_hi <= 0.0) {
        set_move(out, f, 0.0, rest, duration - rest.t_ramp);  // dwell at rest in between
        return Status::ok;
      }
      if (lo == 0.0 && !dwell) {  // T grows without bound as vm -> 0: halve until too slow
        lo = hi;
        do {
          lo *= 0.5;
          g_lo = g(lo);
        } while (g_lo <= 0.0 && lo > 0.0);
      }
      if (g_hi <= 0.0 && g_lo > 0.0) {
        const double vm = solve_bracket(hi, lo, g_hi, g_lo, kResidue * duration, g);
        level_into(f, vm, lim, lv);
        if (lv.dist <= f.d + kResidue * std::max(d_abs, lv.path)) {
          set_move(out, f, vm, lv, cruise_time(f, vm, lv));
          return Status::ok;
        }
        if (n < kCap && vm < at(i) && vm > at(j)) hole = vm;  // split the run there
      }
      i = j + 1;
    }
    if (hole < 0.0) break;
    const auto pos = std::lower_bound(x.begin(), x.begin() + n, hole, std::greater<>());
    const auto k = pos - x.begin();
    std::copy_backward(x.begin() + k, x.begin() + n, x.begin() + n + 1);
    std::copy_backward(gd.begin() + k, gd.begin() + n, gd.begin() + n + 1);
    x[static_cast<std::size_t>(k)] = hole;
    gd[static_cast<std::size_t>(k)] = g_dist(hole);
    ++n;
  }
  return Status::not_supported;
}

// Lowered from the highest feasible level first (the fastest of the family: a start too fast
// for the target, e.g. at the arrival velocity just behind it, can only dip a little, and the
// levels near 0 are out of reach), else from the root bracketed from 0 (where the feasible
// levels are not one interval and the top one cannot be lowered far enough).
Status stretch_in_frame(const Frame& f, double duration, const Limits& lim, Move& out) noexcept {
  if (f.v1 < 0.0) return Status::not_supported;
  Level top;
  const double vm_top = top_level(f, lim, top);
  if (vm_top < 0.0) return Status::not_supported;
  const Status st = stretch_from(f, vm_top, duration, lim, out);
  if (st != Status::not_supported) return st;
  const double vm_zero = stretch_level(f, lim);
  if (vm_zero >= 0.0 && vm_zero != vm_top &&
      stretch_from(f, vm_zero, duration, lim, out) == Status::ok) {
    return Status::ok;
  }
  return stretch_scan(f, vm_top, duration, lim, out);
}

}  // namespace

Status move_of_duration(const State& start, double p1, double v1, double duration,
                        const Limits& lim, Move& out) noexcept {
  if (!valid(lim) || !finite(start) || !std::isfinite(p1) || !std::isfinite(v1) ||
      !std::isfinite(duration) || duration < 0.0 || std::abs(v1) > lim.v_max) {
    return Status::invalid_input;
  }
  // A level search can meet T(vm) = duration at a jump of T(vm) (seen from a start whose
  // release ends beyond V: a 0.178 s move answered for 599 s, jerk/move_test.cpp): such a move
  // is no move of that duration and is refused (not_supported), so that callers try the turn.
  const auto checked = [&](Status st) {
    if (st == Status::ok && !(std::abs(out.time() - duration) <= kRelTol * duration)) {
      return Status::not_supported;
    }
    return st;
  };
  const double sign = natural_sign(start, p1, v1);
  const Status st =
      checked(stretch_in_frame(frame_of(start, p1, v1, sign, lim), duration, lim, out));
  if (st != Status::not_supported) return st;
  // A target the start cannot stop before, at rest or to be met moving back (v1 against the
  // way to it): overshoot and return, the reversed frame (its level is the return velocity;
  // lowering it toward 0 stretches the move without bound).
  return checked(stretch_in_frame(frame_of(start, p1, v1, -sign, lim), duration, lim, out));
}

namespace {

bool valid_request(const State& start, double p1, double v1, const Limits& lim) noexcept {
  return valid(lim) && finite(start) && std::isfinite(p1) && std::isfinite(v1) &&
         std::abs(v1) <= lim.v_max;
}

// The search of fastest_move for inputs already checked (valid_request).
Status fastest_move_in(const State& start, double p1, double v1, const Limits& lim, Move& out,
                       bool curved) noexcept {
  // The natural frame, and for targets approached from the wrong side the reversed one (overshoot
  // and return without a stop in between: to a target at rest, or one to be met moving back);
  // the faster of the two.
  const double sign0 = natural_sign(start, p1, v1);
  double best = std::numeric_limits<double>::infinity();
  for (const double sign : {sign0, -sign0}) {
    // (The reversed frame with v1 != 0: an arrival velocity pointing back from beyond the
    // target; the natural frame then has f.v1 < 0 and is skipped.)
    // (Both skips decided from the frame's values before the frame and its crossing start are
    // built: the reversed frame is mostly skipped.)
    if (sign * v1 < 0.0) continue;
    // A target behind (d < 0) cannot be reached by a frame start that never moves backward
    // (v0 >= 0 and the release velocity v_zero >= 0: every ramp of the family then keeps
    // v >= 0, so every level covers a distance >= 0). Decided before any level is evaluated.
    const double v0 = sign * start.v;
    const double v_zero = release_velocity(v0, sign * start.a, lim);
    if (sign * (p1 - start.p) < 0.0 && v0 >= 0.0 && v_zero >= 0.0) continue;
    const Frame f = frame_of(start, p1, v1, sign, v_zero, lim);
    Level lv;
    const double vm = top_level(f, lim, lv, curved);
    if (vm < 0.0) continue;
    const double t_cruise = cruise_time(f, vm, lv);
    if (lv.t_ramp + t_cruise < best) {
      best = lv.t_ramp + t_cruise;
      set_move(out, f, vm, lv, t_cruise);
    }
    if (f.v0 >= 0.0) break;  // not moving away: no overshoot can be faster than this move
  }
  return best < std::numeric_limits<double>::infinity() ? Status::ok : Status::not_supported;
}

}  // namespace

Status fastest_move(const State& start, double p1, double v1, const Limits& lim,
                    Move& out) noexcept {
  if (!valid_request(start, p1, v1, lim)) return Status::invalid_input;
  return fastest_move_in(start, p1, v1, lim, out, true);
}

Status detail::fastest_move_trusted(const State& start, double p1, double v1, const Limits& lim,
                                    Move& out) noexcept {
  return fastest_move_in(start, p1, v1, lim, out, true);
}

Status detail::fastest_move_newton(const State& start, double p1, double v1, const Limits& lim,
                                   Move& out) noexcept {
  if (!valid_request(start, p1, v1, lim)) return Status::invalid_input;
  return fastest_move_in(start, p1, v1, lim, out, false);
}

State end_state(const State& start, const Move& move) noexcept {
  // Each phase starts from its intended boundary values (docs/axes-profile.md, "Numerics").
  const double s = move.sign;
  State st{s * start.p, s * start.v, s * start.a};
  if (move.cross.time() > 0.0) {
    st = advance(st, move.cross.jerk[0], move.cross.duration[0]);
    st.a = move.cross.a_peak;
    st = advance(st, move.cross.jerk[1], move.cross.duration[1]);
    st.a = move.cross.a_peak;
    st = advance(st, move.cross.jerk[2], move.cross.duration[2]);
    st.a = move.cross.a_zero;
    st.v = 0.0;
  }
  const auto chain = [&](const Ramp& r) {
    st = advance(st, r.jerk[0], r.duration[0]);
    st.a = r.a_peak;
    st = advance(st, r.jerk[1], r.duration[1]);
    st.a = r.a_peak;
    st = advance(st, r.jerk[2], r.duration[2]);
    st.a = 0.0;
    st.v = r.v_end;
  };
  chain(move.first);
  st = advance(st, 0.0, move.t_cruise);
  chain(move.second);
  return State{s * st.p, s * st.v, s * st.a};
}

}  // namespace ncsim::jerk

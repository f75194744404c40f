// axes/profile_general.cpp: position motions from any start state (002_* 2.1 from a moving
// axis, as needed by online changes 2.2 to 2.4, decoupled slaves and sync-in).
//
// Case split (docs/axes-profile.md, "Planning from any state"):
//  1. rest to rest: closed form with the manual's symmetric min(A+, A-) rule (profile_builder);
//  2. moving toward the target and able to arrive: one velocity change to a level vm, [cruise
//     at V], one velocity change to the target velocity. vm = V when the distance allows
//     (closed form); otherwise vm solves distance(vm) = remaining distance, a scalar equation
//     with no closed form in the mixed cases, solved by a bracketed regula falsi (Anderson-Bjorck);
//  3. moving away, or unable to arrive without overshooting: stop, then return (002_* 2.3).

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "axes/profile.hpp"
#include "axes/profile_builder.hpp"
#include "axes/profile_classify.hpp"
#include "axes/profile_outside.hpp"
#include "core/tolerance.hpp"

namespace ncsim::axes {

namespace {

using detail::append_rest_to_rest;
using detail::append_stop;
using detail::distance;
using detail::ProfileBuilder;
using detail::ramp_distance;
using detail::velocity_ramp;

bool finite(const MotionState& s) noexcept {
  return std::isfinite(s.p) && std::isfinite(s.v) && std::isfinite(s.a);
}

// Start within the limits: |v| <= V, |a| <= A- where it slows the motion, A+ where it speeds it
// up, min(A+, A-) at rest.
bool inside_limits(const MotionState& s, const Dynamics& dyn) noexcept {
  const double av = s.a * s.v;
  const double cap = av < 0.0 ? dyn.d_max : (av > 0.0 ? dyn.a_max : std::min(dyn.a_max, dyn.d_max));
  return std::abs(s.v) <= dyn.v_max && std::abs(s.a) <= cap;
}

// Frame distance to rest from frame state (v, a) with v >= 0 moving forward: the acceleration
// clamp (limits first), then the velocity change to zero.
double stop_distance(double v, double a, const Dynamics& dyn) noexcept {
  double p = 0.0;
  const double j = dyn.j_max;
  double t = 0.0;
  double jc = 0.0;
  if (a > dyn.a_max) {
    t = (a - dyn.a_max) / j;
    jc = -j;
  } else if (a < -dyn.d_max) {
    t = (-dyn.d_max - a) / j;
    jc = j;
  }
  if (t > 0.0) {
    p = t * (v + t * (a * 0.5 + t * jc * (1.0 / 6.0)));
    v += t * (a + t * jc * 0.5);
    a += t * jc;
  }
  return p + distance(v, a, velocity_ramp(v, a, 0.0, dyn.a_max, dyn.d_max, j));
}

// Distance of: change (v0, a0) -> (vm, 0), then (vm, 0) -> (vf, 0), in the frame.
double level_distance(double v0, double a0, double vm, double vf, const Dynamics& dyn) noexcept {
  const double j = dyn.j_max;
  return distance(v0, a0, velocity_ramp(v0, a0, vm, dyn.a_max, dyn.d_max, j)) +
         distance(vm, 0.0, velocity_ramp(vm, 0.0, vf, dyn.a_max, dyn.d_max, j));
}

// Level vm in [v_lo, v_hi] with level_distance(vm) == dist, given f(v_lo) <= dist < f(v_hi).
// Regula falsi with the Anderson-Bjorck weight, bisection as a fallback. The tolerance is relative
// to dist only: f(v_hi) can exceed dist by many orders of magnitude (V = 5000 mm/s, A- = 5 mm/s^2
// against a 10 um move), and a tolerance tied to it let the chain miss the target. When the
// bracket has shrunk to rounding size, the lower end is returned: its distance is <= dist, so
// the remaining way is a short cruise and the target is still met.
double solve_level(double v0, double a0, double vf, double dist, double v_lo, double v_hi,
                   double f_lo, double f_hi, const Dynamics& dyn) noexcept {
  double lo = v_lo;
  double hi = v_hi;
  double g_lo = f_lo - dist;
  double g_hi = f_hi - dist;
  const double tol = kResidue * dist;
  int side = 0;
  for (int i = 0; i < 200 && hi - lo > kResidue * hi; ++i) {
    double x = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    const double g = level_distance(v0, a0, x, vf, dyn) - dist;
    if (std::abs(g) <= tol) return x;
    if (g < 0.0) {
      if (side == -1) g_hi *= jerk::detail::anderson_bjorck(g, g_lo);
      lo = x;
      g_lo = g;
      side = -1;
    } else {
      if (side == 1) g_lo *= jerk::detail::anderson_bjorck(g, g_hi);
      hi = x;
      g_hi = g;
      side = 1;
    }
  }
  return lo;
}

// Case 3: stop, then return to the target (and speed up to its velocity on the way).
void append_stop_and_return(ProfileBuilder& b, const PositionTarget& target,
                            const Dynamics& dyn) noexcept {
  append_stop(b, dyn);
  if (target.v == 0.0) {
    append_rest_to_rest(b, target.p, dyn);
    return;
  }
  const double s = target.v > 0.0 ? 1.0 : -1.0;
  const double speed = std::abs(target.v);
  append_rest_to_rest(b, target.p - s * ramp_distance(speed, dyn.a_max, dyn.j_max), dyn);
  b.mark_brake();
  b.set_level(speed);
  b.add(velocity_ramp(0.0, 0.0, speed, dyn.a_max, dyn.d_max, dyn.j_max), s);
}

// ProfileRule::time_optimal: the fastest of the single-peak family, stop-then-go and the manual
// plan (docs/axes-profile.md); a start outside the limits is first brought back inside.
void plan_time_optimal(const MotionState& start, const PositionTarget& target, const Dynamics& dyn,
                       Profile& out) noexcept {
  // A start outside the limits is first brought back inside
  // (axes/profile_outside.hpp, docs/axes-profile-outside.md).
  const bool outside = detail::outside_limits(start, dyn);
  if (outside && detail::plan_from_outside(start, target, dyn, out)) return;
  // A direct move (toward the target, not moving away) is the single-peak family's best,
  // which contains the manual's. To a target at rest from a start within the limits the
  // candidates contain "stop, then the fastest rest-to-rest move", never slower than the
  // manual's stop-and-return (its return uses the symmetric rule). Otherwise the manual planner
  // covers reversals the family cannot, so the faster of both is taken.
  bool direct = false;
  detail::StopPoint stop{-1.0, 0.0};  // t < 0: not computed by plan_fastest
  const bool found = detail::plan_fastest(start, target, dyn, out, direct, stop);
  if (found && (direct || (target.v == 0.0 && inside_limits(start, dyn)))) return;
  // The manual's stop-and-return skipped where its lower bound shows it cannot
  // be faster (axes/profile_classify.hpp).
  // The bound describes the manual plan from inside the limits only (from
  // outside, the manual first recovers: manual_recover).
  if (found && !outside &&
      detail::manual_bound(start, target, dyn, stop.t >= 0.0 ? &stop : nullptr) >= out.duration()) {
    return;
  }
  Profile manual;
  plan_position(start, target, dyn, manual, ProfileRule::manual);
  if (!found || manual.duration() < out.duration()) out = manual;
}

// The manual rule's frame: the direction of arrival (target velocity), else the side of the
// stop point on which the target lies.
double arrival_sign(const MotionState& start, const PositionTarget& target,
                    const Dynamics& dyn) noexcept {
  if (target.v != 0.0) return target.v > 0.0 ? 1.0 : -1.0;
  const double m = detail::motion_sign(start, 1.0);
  const double p_stop = start.p + m * stop_distance(m * start.v, m * start.a, dyn);
  const double d = target.p - p_stop;
  return d > 0.0 ? 1.0 : (d < 0.0 ? -1.0 : m);
}

// Case 2 (V reached, cruise) or the highest level below V whose chain from (v1, a1) to vf fits
// `dist` (docs/axes-profile.md, "Numerics" 4): the level vm and the cruise time. False when no
// level fits (case 3: the axis cannot arrive without overshooting).
bool manual_level(double v1, double a1, double vf, double dist, const Dynamics& dyn, double& vm,
                  double& t_cruise) noexcept {
  const double f_hi = level_distance(v1, a1, dyn.v_max, vf, dyn);
  vm = dyn.v_max;
  t_cruise = 0.0;
  if (f_hi <= dist) {  // case 2, V reached; a cruise of rounding residue length is dropped
    if (dist - f_hi > kResidue * dist) t_cruise = (dist - f_hi) / dyn.v_max;
    return true;
  }
  // The highest level whose chain fits: level_distance dips where a ramp vanishes (at the
  // start's v_zero and at vf), so the feasible levels need not be one interval; candidates
  // are tried from the top and the root is taken between the first that fits and the next
  // higher one.
  const double v_zero = v1 + a1 * std::abs(a1) / (2.0 * dyn.j_max);
  const auto clamp = [&](double v) { return std::clamp(v, 0.0, dyn.v_max); };
  const std::array<double, 3> candidates{clamp(std::max(v_zero, vf)), clamp(std::min(v_zero, vf)),
                                         0.0};
  double v_hi = dyn.v_max;
  double f_top = f_hi;
  double v_lo = -1.0;
  double f_lo = 0.0;
  for (const double c : candidates) {
    if (!(c < v_hi)) continue;
    const double f_c = level_distance(v1, a1, c, vf, dyn);
    if (f_c <= dist) {
      v_lo = c;
      f_lo = f_c;
      break;
    }
    v_hi = c;
    f_top = f_c;
  }
  if (v_lo < 0.0) return false;
  vm = solve_level(v1, a1, vf, dist, v_lo, v_hi, f_lo, f_top, dyn);
  const double rest = dist - level_distance(v1, a1, vm, vf, dyn);
  if (rest > kResidue * dist && vm > 0.0) t_cruise = rest / vm;
  return true;
}

// ProfileRule::manual (002 2.1-2.3): rest to rest (case 1), a single peak at V or below it
// (case 2), or stop and return (case 3).
void plan_manual(const MotionState& start, const PositionTarget& target, const Dynamics& dyn,
                 Profile& out) noexcept {
  // A start whose forced release reverses the motion beyond V or A+ is first
  // brought inside by the manual's own rules (axes/profile_outside.hpp, manual_recover).
  if (detail::outside_limits(start, dyn) &&
      detail::plan_manual_from_outside(start, target, dyn, out)) {
    return;
  }
  ProfileBuilder b(out, start);
  const MotionState end{target.p, target.v, 0.0};
  if (start.v == 0.0 && start.a == 0.0 && target.v == 0.0) {  // case 1
    append_rest_to_rest(b, target.p, dyn);
    b.finish(&end);
    return;
  }
  const double s = arrival_sign(start, target, dyn);
  const double v0 = s * start.v;
  const double a0 = s * start.a;
  if (v0 < 0.0 || (v0 == 0.0 && a0 < 0.0)) {  // case 3, moving away
    append_stop_and_return(b, target, dyn);
    b.finish(&end);
    return;
  }
  detail::clamp_acceleration(b, s, dyn);
  const double v1 = s * b.state().v;
  const double a1 = s * b.state().a;
  const double dist = s * (target.p - b.state().p);
  const double vf = std::abs(target.v);
  const double j = dyn.j_max;
  // A target behind (an arrival velocity pointing away from it) with a start that never moves
  // backward in this frame (v1 >= 0, release velocity v_zero >= 0): every level's chain keeps
  // v >= 0 and covers a distance >= 0 > dist, so no level fits. Case 3 without evaluating one.
  double vm = 0.0;
  double t_cruise = 0.0;
  if ((dist < 0.0 && v1 >= 0.0 && v1 + a1 * std::abs(a1) / (2.0 * j) >= 0.0) ||
      !manual_level(v1, a1, vf, dist, dyn, vm, t_cruise)) {
    append_stop_and_return(b, target, dyn);  // case 3, cannot arrive without overshooting
    b.finish(&end);
    return;
  }
  b.set_level(vm);
  b.add(velocity_ramp(v1, a1, vm, dyn.a_max, dyn.d_max, j), s);
  b.add(0.0, t_cruise);
  b.mark_brake();
  b.add(velocity_ramp(vm, 0.0, vf, dyn.a_max, dyn.d_max, j), s);
  b.finish(&end);
}

}  // namespace

Result plan_position(const MotionState& start, const PositionTarget& target, const Dynamics& dyn,
                     Profile& out, ProfileRule rule) noexcept {
  if (!valid(dyn) || !finite(start) || !std::isfinite(target.p) || !std::isfinite(target.v) ||
      std::abs(target.v) > dyn.v_max) {
    return Result::error_invalid_input;
  }
  if (rule == ProfileRule::time_optimal)
    plan_time_optimal(start, target, dyn, out);
  else
    plan_manual(start, target, dyn, out);
  return Result::ok;
}

}  // namespace ncsim::axes

// axes/profile_classify.cpp: lower bounds that let the time-optimal rule skip candidates that
// cannot win (see profile_classify.hpp).
//
// Each bound is the candidate's own closed-form parts (the stop's phases, the fastest
// rest-to-rest time, the final ramp to the arrival speed) over a distance shortened by a
// rounding margin, times (1 - kRelTol): the candidates' durations are sums of the same phases
// integrated by the profile builder, equal to these to ~1e-15 relative.
//  - "stop, then go": t_stop + T_r2r(|p1 - p_stop|) for a target at rest (the fastest
//    rest-to-rest move is the closed form); for an arrival velocity v1 infinite where the go
//    part (the single peak from rest) cannot exist, the target closer than the ramp 0 -> |v1|
//    or behind, else t_stop + T_r2r(|q - p_stop|) - the ramp |v1| -> 0 under A- (q: where that
//    ramp appended to the go part ends).
//  - the manual's stop-and-return (frame of the arrival velocity, start moving against it, or
//    never moving backward with the target behind and no acceleration clamp):
//    t_stop + T_man(|q - p_stop|) + the ramp 0 -> |v1|, q = p1 - sign(v1) ramp_distance(|v1|),
//    T_man the manual's rest-to-rest time (its level from the symmetric min(A+, A-)) in closed
//    form: the plan's own parts, so the bound is the plan's duration less the margins.
//  - the two-peak change (jerk/two_peak.cpp): it has no cruise and its velocity is monotone
//    between v0 and v1 (its dip does not cross a = 0), so it covers D in a time T with
//    D <= max(|v0|, |v1|) T, and T is at least the time-optimal velocity change v0 -> v1
//    (velocity_ramp) under the larger of A+, A- (larger limits are never slower).

#include "axes/profile_classify.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "axes/profile_builder.hpp"
#include "core/tolerance.hpp"

namespace ncsim::axes::detail {

namespace {

constexpr double kMargin = kRelTol;  // relative rounding margin of every bound

// Distance shortened by the rounding margin of the positions it is computed from [mm].
double shortened(double dist, double scale) noexcept {
  return std::max(0.0, dist - kMargin * (dist + scale));
}

// Duration [s] of the manual rule's rest-to-rest move over dist >= 0 [mm]
// (append_rest_to_rest, 002_* 2.1): the level from the symmetric min(A+, A-), the ramps under
// the real A+ and A-, the cruise dropped where it is a rounding residue; its phases' sum to
// rounding (1e-15), without building them.
double manual_rest_to_rest_time(double dist, const Dynamics& dyn) noexcept {
  if (!(dist > 0.0)) return 0.0;
  const double j = dyn.j_max;
  const double a_sym = std::min(dyn.a_max, dyn.d_max);
  double v_reach = 0.0;
  if (dist * j * j <= 2.0 * a_sym * a_sym * a_sym) {
    v_reach = std::cbrt(0.25 * dist * dist * j);
  } else {
    const double r = a_sym / j;
    v_reach = 0.5 * a_sym * (std::sqrt(r * r + 4.0 * dist / a_sym) - r);
  }
  const double vm = std::min(dyn.v_max, v_reach);
  const double d_cruise = dist - ramp_distance(vm, dyn.a_max, j) - ramp_distance(vm, dyn.d_max, j);
  const double t_cruise = d_cruise > kResidue * dist ? d_cruise / vm : 0.0;
  return rest_ramp_time(vm, dyn.a_max, j) + t_cruise + rest_ramp_time(vm, dyn.d_max, j);
}

}  // namespace

StopPoint stop_point(const MotionState& start, const Dynamics& dyn) noexcept {
  // append_stop: the motion's sign, the clamp of an acceleration beyond its limit, the ramp.
  const double s = motion_sign(start, 1.0);
  const double j = dyn.j_max;
  double v = s * start.v;
  double a = s * start.a;
  double t = 0.0;
  double p = 0.0;
  double t_clamp = 0.0;
  double j_clamp = 0.0;
  if (a > dyn.a_max) {
    t_clamp = (a - dyn.a_max) / j;
    j_clamp = -j;
  } else if (a < -dyn.d_max) {
    t_clamp = (-dyn.d_max - a) / j;
    j_clamp = j;
  }
  if (t_clamp > 0.0) {
    const jerk::State st = jerk::advance(jerk::State{0.0, v, a}, j_clamp, t_clamp);
    p = st.p;
    v = st.v;
    a = j_clamp > 0.0 ? -dyn.d_max : dyn.a_max;
    t = t_clamp;
  }
  const Ramp stop = velocity_ramp(v, a, 0.0, dyn.a_max, dyn.d_max, j);
  return StopPoint{t + stop.time(), start.p + s * (p + distance(v, a, stop))};
}

double stop_then_go_bound(const MotionState& start, const PositionTarget& target,
                          const Dynamics& dyn, StopPoint* stop_out) noexcept {
  const StopPoint stop = stop_point(start, dyn);
  if (stop_out != nullptr) *stop_out = stop;
  if (target.v == 0.0) {
    const double scale = std::abs(stop.p - start.p) + std::abs(target.p - start.p);
    const double dist = shortened(std::abs(target.p - stop.p), scale);
    return (stop.t + rest_to_rest_fastest_time(dist, dyn)) * (1.0 - kMargin);
  }
  // An arrival velocity (issue 11, session 26): the go part is jerk::fastest_move from rest in
  // the frame g of v1 (its reversed frame needs v1 against g: skipped). Every level's chain from
  // rest covers at least the direct ramp 0 -> |v1| under A+ (the ramp's acceleration at each
  // velocity, min(sqrt(2 J v), A+, sqrt(2 J (|v1| - v))), bounds every accelerating profile
  // from rest, so it covers the least distance; a level above |v1| covers more already on its
  // way up): a target closer than that, or behind, has no go part.
  const double g = target.v > 0.0 ? 1.0 : -1.0;
  const double speed = std::abs(target.v);
  const double j = dyn.j_max;
  const double up = ramp_distance(speed, dyn.a_max, j);
  const double ahead = g * (target.p - stop.p);
  const double scale = std::abs(stop.p - start.p) + std::abs(target.p - start.p) + up;
  if (ahead < up - kMargin * scale) return std::numeric_limits<double>::infinity();
  // Else: the go part followed by the stop ramp |v1| -> 0 under A- is a rest-to-rest move over
  // |q - p_stop|, q = p1 + g ramp_distance(|v1|, A-), never faster than the fastest one, so
  // the go part takes at least T_r2r(|q - p_stop|) less the stop ramp's time.
  const double down = ramp_distance(speed, dyn.d_max, j);
  const double dist = shortened(std::abs(ahead + down), scale + down);
  const double t_down = rest_ramp_time(speed, dyn.d_max, j);
  const double t_r2r = rest_to_rest_fastest_time(dist, dyn);
  return stop.t + t_r2r - t_down - kMargin * (stop.t + t_r2r + t_down);
}

double manual_bound(const MotionState& start, const PositionTarget& target, const Dynamics& dyn,
                    const StopPoint* known) noexcept {
  // plan_position's manual rule for an arrival velocity: frame of the arrival; a start moving
  // against it (or at rest accelerating against it) stops and returns (its case 3). So does a
  // start that never moves backward in that frame with the target behind it (its v_zero test;
  // taken here only where the start needs no clamp of its acceleration, so the test sees the
  // start's own values, bit for bit the manual's): 260 of the 289 plans of the bench that built
  // the manual plan to compare it (issue 11, session 28).
  if (target.v == 0.0) return 0.0;
  const double s = target.v > 0.0 ? 1.0 : -1.0;
  const double v0 = s * start.v;
  const double a0 = s * start.a;
  const bool away = v0 < 0.0 || (v0 == 0.0 && a0 < 0.0);
  const bool behind = a0 <= dyn.a_max && a0 >= -dyn.d_max && s * (target.p - start.p) < 0.0 &&
                      v0 >= 0.0 && v0 + a0 * std::abs(a0) / (2.0 * dyn.j_max) >= 0.0;
  if (!away && !behind) return 0.0;
  // (The stop point of stop_then_go_bound where plan_fastest computed it: issue 11, session 28.)
  const StopPoint stop = known != nullptr ? *known : stop_point(start, dyn);
  const double speed = std::abs(target.v);
  const double q = target.p - s * ramp_distance(speed, dyn.a_max, dyn.j_max);
  const double scale = std::abs(stop.p - start.p) + std::abs(q - start.p);
  const double dist = shortened(std::abs(q - stop.p), scale);
  const double t_ramp = velocity_ramp(0.0, 0.0, speed, dyn.a_max, dyn.d_max, dyn.j_max).time();
  // The manual's own rest-to-rest time, not the fastest one under the real A+, A- (issue 11,
  // session 28): the bound is then the plan's duration less the margins.
  return (stop.t + manual_rest_to_rest_time(dist, dyn) + t_ramp) * (1.0 - kMargin);
}

double two_peak_bound(const MotionState& start, const PositionTarget& target, const Dynamics& dyn,
                      double enough) noexcept {
  const double dist = std::abs(target.p - start.p);
  const double a_big = std::max(dyn.a_max, dyn.d_max);
  if (!(dist > 0.0) || !(std::abs(start.a) <= a_big)) return 0.0;
  const double v_high = std::max(std::abs(start.v), std::abs(target.v));
  const double t_way =
      (v_high > 0.0 ? dist / v_high : std::numeric_limits<double>::infinity()) * (1.0 - kMargin);
  if (t_way >= enough) return t_way;
  const double t_change = velocity_ramp(start.v, start.a, target.v, a_big, a_big, dyn.j_max).time();
  return std::max(t_way, t_change * (1.0 - kMargin));
}

}  // namespace ncsim::axes::detail

// axes/profile_optimal.cpp: profiles where the manual prescribes nothing (docs/axes-profile.md,
// "Profile rule", "Synchronised and moving targets"):
//  - ProfileRule::time_optimal: the fastest single-peak profile (jerk::fastest_move);
//  - a prescribed duration: the single-peak profile with a lowered level (jerk::move_of_duration);
//  - time-synchronised axes: every axis gets the longest single-axis duration;
//  - a target moving with constant velocity: the earliest meeting time, found by growing the
//    time geometrically until the single-peak family can meet p1 + v1 T in time, then
//    bisecting between the last time it could not and the first it could.

#include <algorithm>
#include <cmath>
#include <limits>

#include "axes/profile.hpp"
#include "axes/profile_builder.hpp"

namespace ncsim::axes {

namespace detail {

void append_move(ProfileBuilder& b, const jerk::Move& m) noexcept {
  b.set_level(m.v_level);
  b.add(m.first, m.sign);
  b.add(0.0, m.t_cruise);
  b.mark_brake();
  b.add(m.second, m.sign);
}

bool plan_fastest(const MotionState& start, const PositionTarget& target, const Dynamics& dyn,
                  Profile& out) noexcept {
  // Candidate 1: one single-peak move (reversing without a stop where the target lies behind).
  // Candidate 2 (starts moving away): stop with A-, then the fastest move from rest; a
  // reversing ramp can only use min(A+, A-) across v = 0, so the stop can be faster.
  const MotionState end{target.p, target.v, 0.0};
  jerk::Move m;
  bool found = false;
  if (jerk::fastest_move(start, target.p, target.v, dyn, m) == jerk::Status::ok) {
    ProfileBuilder b(out, start);
    append_move(b, m);
    b.finish(&end);
    found = true;
  }
  if (start.v == 0.0 && start.a == 0.0) return found;
  Profile alt;
  ProfileBuilder b(alt, start);
  append_stop(b, dyn);
  const MotionState rest{b.state().p, 0.0, 0.0};
  if (jerk::fastest_move(rest, target.p, target.v, dyn, m) != jerk::Status::ok) return found;
  append_move(b, m);
  b.finish(&end);
  if (!found || alt.duration() < out.duration()) out = alt;
  return true;
}

}  // namespace detail

namespace {

bool finite(const MotionState& s) noexcept {
  return std::isfinite(s.p) && std::isfinite(s.v) && std::isfinite(s.a);
}

}  // namespace

Result plan_position_of_duration(const MotionState& start, const PositionTarget& target,
                                 const Dynamics& dyn, double duration, Profile& out) noexcept {
  jerk::Move m;
  const jerk::Status st = jerk::move_of_duration(start, target.p, target.v, duration, dyn, m);
  if (st == jerk::Status::invalid_input) return Result::error_invalid_input;
  if (st != jerk::Status::ok) return Result::error_not_synchronizable;
  detail::ProfileBuilder b(out, start);
  detail::append_move(b, m);
  const MotionState end{target.p, target.v, 0.0};
  b.finish(&end);
  return Result::ok;
}

Result plan_synchronized(std::span<const MotionState> starts,
                         std::span<const PositionTarget> targets,
                         std::span<const Dynamics> dynamics, ProfileRule rule, double min_duration,
                         std::span<Profile> out) noexcept {
  const std::size_t n = starts.size();
  if (targets.size() != n || dynamics.size() != n || out.size() != n ||
      !std::isfinite(min_duration)) {
    return Result::error_invalid_input;
  }
  double t_sync = std::max(min_duration, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const Result r = plan_position(starts[i], targets[i], dynamics[i], out[i], rule);
    if (r != Result::ok) return r;
    t_sync = std::max(t_sync, out[i].duration());
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (out[i].duration() == t_sync) continue;  // the slowest axis keeps its own profile
    const Result r = plan_position_of_duration(starts[i], targets[i], dynamics[i], t_sync, out[i]);
    if (r != Result::ok) return r;
  }
  return Result::ok;
}

Result plan_moving_target(const MotionState& start, double p1, double v1, const Dynamics& dyn,
                          Profile& out, double& t_meet) noexcept {
  if (!valid(dyn) || !finite(start) || !std::isfinite(p1) || !std::isfinite(v1) ||
      std::abs(v1) > dyn.v_max) {
    return Result::error_invalid_input;
  }
  // can_meet(T): the time-optimal profile reaches p1 + v1 T with velocity v1 in at most T.
  Profile probe;
  const auto can_meet = [&](double t) {
    return plan_position(start, PositionTarget{p1 + v1 * t, v1}, dyn, probe,
                         ProfileRule::time_optimal) == Result::ok &&
           probe.duration() <= t;
  };
  // Grow T from well below the static target's time, so an approaching target is met early.
  const bool static_ok = plan_position(start, PositionTarget{p1, v1}, dyn, probe,
                                       ProfileRule::time_optimal) == Result::ok;
  double t_hi = (static_ok && probe.duration() > 0.0 ? probe.duration() : 1.0) * 0x1p-20;
  double t_lo = 0.0;
  if (can_meet(0.0)) {
    t_hi = 0.0;
  } else {
    int k = 0;
    while (!can_meet(t_hi)) {
      t_lo = t_hi;
      t_hi *= 2.0;
      if (++k > 100) return Result::error_not_synchronizable;  // the target runs away
    }
    // Earliest: shrink [t_lo, t_hi] to rounding, keeping can_meet(t_hi).
    for (int i = 0; i < 200 && t_hi - t_lo > 4.0 * std::numeric_limits<double>::epsilon() * t_hi;
         ++i) {
      const double mid = 0.5 * (t_lo + t_hi);
      (can_meet(mid) ? t_hi : t_lo) = mid;
    }
  }
  t_meet = t_hi;
  const PositionTarget target{p1 + v1 * t_hi, v1};
  // A meeting time found means a profile of exactly that duration exists unless the family
  // cannot be stretched to it (a moving start that would have to reverse).
  if (plan_position_of_duration(start, target, dyn, t_hi, out) == Result::ok) {
    t_meet = out.duration();  // T to rounding; the profile's own end is the meeting
    return Result::ok;
  }
  // At the meeting time the fastest profile itself takes T (to rounding).
  if (plan_position(start, target, dyn, out, ProfileRule::time_optimal) == Result::ok &&
      std::abs(out.duration() - t_hi) <= 1e-9 * t_hi) {
    t_meet = out.duration();
    return Result::ok;
  }
  return Result::error_not_synchronizable;
}

}  // namespace ncsim::axes

// axes/phase_sync.cpp: phase-synchronised multi-axis motion (see phase_sync.hpp,
// docs/axes-phase-sync.md). The common motion u: 0 -> 1 is planned once under the tightest
// scaled limits; every axis's profile is its phases with the jerk scaled by the distance D_i.

#include "axes/phase_sync.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "axes/profile_builder.hpp"
#include "core/tolerance.hpp"

namespace ncsim::axes {

namespace {

bool at_rest(const MotionState& s) noexcept {
  return s.v == 0.0 && s.a == 0.0;
}

// Axis profile p0 + D u(t): the phases of `u` with jerk and acceleration scaled by D.
void scale_profile(const Profile& u, const MotionState& start, double dist,
                   const PositionTarget& target, Profile& out) noexcept {
  detail::ProfileBuilder b(out, start);
  const auto phases = u.phases();
  b.set_level(std::abs(dist) * u.v_level());
  bool braked = false;
  for (std::size_t i = 0; i < phases.size(); ++i) {
    if (!braked && phases[i].t_start >= u.t_brake()) {
      b.mark_brake();
      braked = true;
    }
    const double a_next = i + 1 < phases.size() ? phases[i + 1].a : 0.0;
    b.add(dist * phases[i].j, phases[i].duration, dist * a_next);
  }
  if (!braked) b.mark_brake();
  const MotionState end{target.p, 0.0, 0.0};
  b.finish(&end);
}

}  // namespace

Result plan_phase_synchronized(std::span<const MotionState> starts,
                               std::span<const PositionTarget> targets,
                               std::span<const Dynamics> dynamics, ProfileRule rule,
                               double min_duration, std::span<Profile> out,
                               SyncKind* used) noexcept {
  const std::size_t n = starts.size();
  if (targets.size() != n || dynamics.size() != n || out.size() != n ||
      !std::isfinite(min_duration)) {
    return Result::error_invalid_input;
  }
  const auto time_sync = [&] {
    if (used != nullptr) *used = SyncKind::time;
    return plan_synchronized(starts, targets, dynamics, rule, min_duration, out);
  };
  // The tightest scaled limits; the slowest axis alone.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Dynamics du{kInf, kInf, kInf, kInf};
  double t_slowest = 0.0;
  bool moving = false;
  for (std::size_t i = 0; i < n; ++i) {
    const Dynamics& d = dynamics[i];
    if (!valid(d) || !std::isfinite(starts[i].p) || !std::isfinite(targets[i].p)) {
      return Result::error_invalid_input;
    }
    if (!at_rest(starts[i]) || targets[i].v != 0.0) return time_sync();
    const double dist = std::abs(targets[i].p - starts[i].p);
    if (dist == 0.0) continue;
    moving = true;
    du.v_max = std::min(du.v_max, d.v_max / dist);
    du.a_max = std::min(du.a_max, d.a_max / dist);
    du.d_max = std::min(du.d_max, d.d_max / dist);
    du.j_max = std::min(du.j_max, d.j_max / dist);
    const Result r = plan_position(starts[i], targets[i], d, out[i], rule);
    if (r != Result::ok) return r;
    t_slowest = std::max(t_slowest, out[i].duration());
  }
  if (!moving) {  // nothing moves: every axis rests for min_duration (TIME=), else 0 s
    for (std::size_t i = 0; i < n; ++i) {
      detail::ProfileBuilder b(out[i], starts[i]);
      b.add(0.0, std::max(min_duration, 0.0));
      const MotionState end{targets[i].p, 0.0, 0.0};
      b.finish(&end);
    }
    if (used != nullptr) *used = SyncKind::phase;
    return Result::ok;
  }
  if (!valid(du)) return time_sync();  // distances below any scale of the limits
  Profile u;
  const MotionState u0{};
  const PositionTarget u1{1.0, 0.0};
  if (plan_position(u0, u1, du, u, rule) != Result::ok) return time_sync();
  if (u.duration() > t_slowest * (1.0 + kRelTol))
    return time_sync();  // the phases cannot be shared
  if (min_duration > u.duration() &&
      plan_position_of_duration(u0, u1, du, min_duration, u) != Result::ok) {
    return time_sync();
  }
  // An axis that does not move rests for the common duration (jerk 0 in every phase).
  for (std::size_t i = 0; i < n; ++i) {
    scale_profile(u, starts[i], targets[i].p - starts[i].p, targets[i], out[i]);
  }
  if (used != nullptr) *used = SyncKind::phase;
  return Result::ok;
}

}  // namespace ncsim::axes

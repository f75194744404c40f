// axes/profile.cpp: evaluation of a Profile (pure, closed form) and the small helpers of
// profile.hpp. Planning lives in profile_rest.cpp, profile_general.cpp, profile_velocity.cpp.

#include "axes/profile.hpp"

#include <algorithm>
#include <cmath>

namespace ncsim::axes {

std::string_view diagnostic_id(Result result) noexcept {
  switch (result) {
    case Result::ok:
    case Result::working:
    case Result::finished:
      return {};
    case Result::error_invalid_input:
      return "NC5001";
    case Result::error_velocity_limit:
      return "NC5002";
    case Result::ignored_braking_phase:
      return "NC5010";
    case Result::rejected_stopping:
      return "NC5011";
    case Result::rejected_compensation_active:
      return "NC5012";
    case Result::rejected_not_moving:
      return "NC5013";
    case Result::ignored_below_increment:
      return "NC5014";
    case Result::error_not_synchronizable:
      return "NC5015";
  }
  return {};
}

std::string_view describe(Result result) noexcept {
  switch (result) {
    case Result::ok:
      return "request accepted";
    case Result::working:
      return "motion in progress";
    case Result::finished:
      return "target reached";
    case Result::error_invalid_input:
      return "invalid motion parameter (not finite, not positive, or target velocity above V)";
    case Result::error_velocity_limit:
      return "requested velocity above the maximum permitted axis velocity";
    case Result::ignored_braking_phase:
      return "request ignored: the axis is already in its braking phase";
    case Result::rejected_stopping:
      return "request rejected: a stop is active and has priority";
    case Result::rejected_compensation_active:
      return "request rejected: a position compensation is active";
    case Result::rejected_not_moving:
      return "request rejected: the axis has not been started";
    case Result::ignored_below_increment:
      return "no start: distance shorter than one encoder increment";
    case Result::error_not_synchronizable:
      return "not supported: no single-peak profile of the required duration (would reverse)";
  }
  return {};
}

double critical_jerk(const Dynamics& dynamics) noexcept {
  // 002_* 2.1 "kritischer Ruck": J+- = (A+-)^2 / V; both limits reached when J >= the larger.
  const double a = std::max(dynamics.a_max, dynamics.d_max);
  return a * a / dynamics.v_max;
}

Dynamics rescale_jerk(const Dynamics& dynamics, double t_cycle) noexcept {
  Dynamics out = dynamics;
  if (!(t_cycle > 0.0)) return out;
  const double a_min = std::min(dynamics.a_max, dynamics.d_max);
  if (a_min / dynamics.j_max < t_cycle) out.j_max = a_min / t_cycle;
  return out;
}

Profile Profile::at_rest(double p) noexcept {
  Profile profile;
  profile.start_ = MotionState{p, 0.0, 0.0};
  profile.end_ = profile.start_;
  return profile;
}

Setpoint Profile::at(double t) const noexcept {
  if (t >= duration_ || count_ == 0) {
    const double dt = std::max(0.0, t - duration_);
    return Setpoint{end_.p + end_.v * dt, end_.v, end_.a, 0.0};
  }
  if (t <= 0.0) return Setpoint{start_.p, start_.v, start_.a, phases_[0].j};
  std::size_t i = 0;
  while (i + 1 < count_ && phases_[i + 1].t_start <= t)
    ++i;
  const Phase& ph = phases_[i];
  const double dt = t - ph.t_start;
  return Setpoint{ph.p + dt * (ph.v + dt * (ph.a * 0.5 + dt * ph.j * (1.0 / 6.0))),
                  ph.v + dt * (ph.a + dt * ph.j * 0.5), ph.a + dt * ph.j, ph.j};
}

}  // namespace ncsim::axes

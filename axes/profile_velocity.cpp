// axes/profile_velocity.cpp: velocity targets (endless motion, MC_MoveVelocity) and stops.
//
// A velocity target is one velocity change (002_* 2.1 phases 1-3 or 5-7) in the frame of the
// motion; a change of sign stops first with A- and then speeds up the other way with A+
// (path quantities, 002_* 2.1 "Bahnbeschleunigung"). Acceleration beyond the limits is first
// taken back to the limit with J (docs/axes-profile.md).

#include <cmath>

#include "axes/profile.hpp"
#include "axes/profile_builder.hpp"

namespace ncsim::axes {

namespace {

bool finite(const MotionState& s) noexcept {
  return std::isfinite(s.p) && std::isfinite(s.v) && std::isfinite(s.a);
}

bool valid_ramps(const Dynamics& d) noexcept {
  const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  return positive(d.a_max) && positive(d.d_max) && positive(d.j_max);
}

}  // namespace

Result plan_velocity(const MotionState& start, double v_target, const Dynamics& dyn,
                     Profile& out) noexcept {
  if (!valid_ramps(dyn) || !finite(start) || !std::isfinite(v_target)) {
    return Result::error_invalid_input;
  }
  detail::ProfileBuilder b(out, start);
  const double target_sign = v_target > 0.0 ? 1.0 : (v_target < 0.0 ? -1.0 : 0.0);
  double s = detail::motion_sign(start, target_sign == 0.0 ? 1.0 : target_sign);
  if (target_sign != 0.0 && target_sign != s) {
    detail::append_stop(b, dyn);
    s = target_sign;
  }
  detail::clamp_acceleration(b, s, dyn);
  const MotionState& st = b.state();
  b.mark_brake();
  b.set_level(std::abs(v_target));
  b.add(detail::velocity_ramp(s * st.v, s * st.a, std::abs(v_target), dyn.a_max, dyn.d_max,
                              dyn.j_max),
        s);
  MotionState end = b.state();
  end.v = v_target;
  b.finish(&end);
  return Result::ok;
}

Result plan_stop(const MotionState& start, const Dynamics& dyn, Profile& out) noexcept {
  if (!valid_ramps(dyn) || !finite(start)) return Result::error_invalid_input;
  detail::ProfileBuilder b(out, start);
  detail::append_stop(b, dyn);
  MotionState end = b.state();
  end.v = 0.0;
  b.finish(&end);
  return Result::ok;
}

}  // namespace ncsim::axes

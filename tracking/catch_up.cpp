// tracking/catch_up: the synchronisation movement after #SYNC IN (see the header).

#include "tracking/catch_up.hpp"

#include <algorithm>
#include <cmath>

namespace ncsim::tracking {

namespace {

using axes::MotionState;
using axes::PositionTarget;
using axes::Profile;
using axes::Result;

}  // namespace

Result plan_meeting(const MotionState& start, double p1, double w, double r,
                    const axes::Dynamics& dyn, Profile& out, double& t_meet) noexcept {
  return axes::plan_moving_target(start, p1, w, w + r, dyn, out, t_meet);
}

namespace {

// The axis in the frame moving with its target's velocity w: the target stands, the axis
// starts at velocity v - w, and |v' + w| <= V holds wherever |v'| <= V - |w|.
MotionState in_belt_frame(const MotionState& s, double w) noexcept {
  return {s.p, s.v - w, s.a};
}

axes::Dynamics belt_frame_dynamics(axes::Dynamics d, double w) noexcept {
  d.v_max -= std::abs(w);
  return d;
}

}  // namespace

Result CatchUp::plan(std::span<const CatchUpAxis> axes, double s0, double v_belt) noexcept {
  n_ = 0;
  duration_ = 0.0;
  failed_ = -1;
  s0_ = s0;
  v_belt_ = v_belt;
  if (axes.empty() || axes.size() > kMaxAxes || !std::isfinite(s0) || !std::isfinite(v_belt)) {
    return Result::error_invalid_input;
  }
  n_ = axes.size();
  // 1. Each axis alone: its earliest meeting with its target p1 + w t. Where the PTP core's
  // single-peak family has no such profile in MCS (a moving axis ahead of a faster target
  // would need a velocity dip below both its start and end velocity), the axis is planned in
  // the frame moving with its target: an ordinary position move there (stop and return
  // included), under V - |w|.
  std::size_t slowest = 0;
  for (std::size_t i = 0; i < n_; ++i) {
    axes_[i] = axes[i];
    belt_frame_[i] = false;
    const CatchUpAxis& a = axes_[i];
    const double w = a.conveying * v_belt;
    double t = 0.0;
    Result r = plan_meeting(a.start, a.target, w, a.v_relative, a.dynamics, profiles_[i], t);
    if (r == Result::error_not_synchronizable && w != 0.0) {
      const axes::Dynamics d = belt_frame_dynamics(a.dynamics, w);
      r = axes::valid(d) ? axes::plan_position(in_belt_frame(a.start, w),
                                               PositionTarget{a.target, a.v_relative}, d,
                                               profiles_[i], axes::ProfileRule::time_optimal)
                         : Result::error_invalid_input;
      belt_frame_[i] = r == Result::ok;
      t = profiles_[i].duration();
    }
    if (r != Result::ok) {
      failed_ = static_cast<int>(i);
      return r;
    }
    meet_[i] = t;
    if (t > duration_) {
      duration_ = t;
      slowest = i;
    }
  }
  // 2. Every other axis in exactly T: the target is then at p1 + w T (MCS), or still at p1
  // in the frame moving with it.
  for (std::size_t i = 0; i < n_; ++i) {
    if (i == slowest || meet_[i] == duration_) continue;
    const CatchUpAxis& a = axes_[i];
    const double w = a.conveying * v_belt;
    Profile stretched;
    if (axes::plan_position_of_duration(a.start,
                                        PositionTarget{a.target + w * duration_, w + a.v_relative},
                                        a.dynamics, duration_, stretched) == Result::ok) {
      profiles_[i] = stretched;
      belt_frame_[i] = false;
      meet_[i] = duration_;
      continue;
    }
    const axes::Dynamics d = belt_frame_dynamics(a.dynamics, w);
    if (w != 0.0 && axes::valid(d) &&
        axes::plan_position_of_duration(in_belt_frame(a.start, w),
                                        PositionTarget{a.target, a.v_relative}, d, duration_,
                                        stretched) == Result::ok) {
      profiles_[i] = stretched;
      belt_frame_[i] = true;
      meet_[i] = duration_;
      continue;
    }
    // Not stretchable: an axis meeting at the target's velocity meets early and rides along
    // (Profile::at continues at the end velocity); one meeting at another velocity would
    // drift away from its target before T.
    if (a.v_relative != 0.0) {
      failed_ = static_cast<int>(i);
      return Result::error_not_synchronizable;
    }
  }
  return Result::ok;
}

axes::Setpoint CatchUp::setpoint(std::size_t i, double t, double s, double v,
                                 double a) const noexcept {
  axes::Setpoint sp = profiles_[i].at(t);
  if (belt_frame_[i]) {  // back from the frame moving with the forecast target
    const double w = axes_[i].conveying * v_belt_;
    sp.p += w * t;
    sp.v += w;
  }
  // The plan forecast the belt at constant velocity v_belt_ from s0_; its deviation from that
  // forecast moves the target, and with it the axis.
  const double c = axes_[i].conveying;
  if (c != 0.0) {
    sp.p += c * (s - s0_ - v_belt_ * t);
    sp.v += c * (v - v_belt_);
    sp.a += c * a;
  }
  return sp;
}

double CatchUp::target_at(std::size_t i, double s) const noexcept {
  return axes_[i].target + axes_[i].conveying * (s - s0_);
}

}  // namespace ncsim::tracking

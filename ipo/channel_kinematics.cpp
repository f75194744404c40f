// ipo/channel_kinematics: step 2 of the channel cycle under #TRAFO ON (docs/ipo.md
// "Kinematics in run and time").
//
// The path interpolator gives the TCP (X, Y, Z Cartesian, other axes as they are) with its
// closed-form v, a, j; the joint stage (ipo/joint_stage.hpp) turns them into the setpoints of
// the machine axes, which the position control and the monitors then act on: soft limits, lag
// and the exact-stop window are the joints'. A point the inverse transform cannot map (the
// adapter and the planner check every block before, so only a broken invariant of theirs gets
// here) stops the channel with the kinematic's workspace error NC3201 at the active block.

#include <cstdio>
#include <string>

#include "ipo/channel.hpp"
#include "ipo/program_source.hpp"

namespace ncsim::ipo {

bool Channel::map_joints(const Cycle& c) noexcept {
  transformed_ = true;
  if (ipo_.override_factor() > 1.0) {
    // Above 100 % the raised cap is the axes' G00 velocity along the path (docs/ipo.md
    // "Override and feed hold"): for the TCP these are stand-ins, not the joints' limits.
    stop(kNotSupportedId,
         "not supported: path override above 100 % under #TRAFO ON (the raised cap does not "
         "know the joints' limits)",
         c, -1);
    return false;
  }
  JointSetpoint s;
  if (!stage_->step(c.x, c.v, c.a, c.j, s)) {
    const AxisVec& p = stage_->failed_point();
    char text[200];
    std::snprintf(text, sizeof text,
                  "TCP point (%.6g, %.6g, %.6g) mm outside the workspace of the kinematic "
                  "transform",
                  p[0], p[1], p[2]);
    stop("NC3201", text, c, -1);
    return false;
  }
  joints_ = s;
  for (std::size_t i = 0; i < axes_.size(); ++i)
    setpoint_[i] = axes::Setpoint{s.q[i], s.v[i], s.a[i], s.j[i]};
  return true;
}

}  // namespace ncsim::ipo

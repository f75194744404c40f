// channel/axis_mapping: the path point -> the machine axes' setpoints (see the header).

#include "channel/axis_mapping.hpp"

namespace ncsim::channel {

void AxisMapping::set_shares() noexcept {
  for (std::size_t i = 0; i < sync_->axis_count(); ++i)
    belt_.share[i] = sync_->share(i);
}

bool AxisMapping::map(const ipo::Cycle& c) noexcept {
  // Identity outside #TRAFO: the path is planned in machine axis values (MCS). The conveyor's
  // moving PCS1 frame turns c.x, c.v, c.a, c.j into the setpoints of the machine axes, which
  // everything after drives and monitors. Under #TRAFO ON the kinematic stage gives the joints;
  // the PCS1 frame and the catch-up act on the TCP there, before the kinematic.
  belt_.following = false;  // the audit's belt share (set below)
  // Where a catch-up / departure left the path, it stands until its next block moves.
  std::optional<planner::AxisVec>& hold = tracking_.hold();
  if (c.activity == ipo::Activity::motion) hold.reset();
  if (kin_.decide(c)) return kin_.map(c, hold, sync_ ? &*sync_ : nullptr, t_cycle_, axes_, error_);
  std::array<axes::Setpoint, planner::kMaxAxes>& setpoint = axes_.setpoints();
  for (std::size_t i = 0; i < axes_.size(); ++i)
    setpoint[i] = axes::Setpoint{c.x[i], c.v[i], c.a[i], c.j[i]};
  // The catch-up / departure drive the axes; PCS1 moves with the belt.
  if (hold)
    for (std::size_t i = 0; i < axes_.size(); ++i)
      setpoint[i] = axes::Setpoint{(*hold)[i]};
  if (sync_ && sync_->driving()) {
    for (std::size_t i = 0; i < axes_.size(); ++i)
      setpoint[i] = sync_->catch_up_setpoint(i);
  } else if (sync_ && sync_->moving_frame()) {
    for (std::size_t i = 0; i < axes_.size(); ++i) {
      setpoint[i].p += sync_->offset(i);
      setpoint[i].v += sync_->offset_v(i);
      setpoint[i].a += sync_->offset_a(i);
    }
  }
  if (sync_ && sync_->following()) {
    belt_.following = true;
    belt_.travel = sync_->travel();
    belt_.acceleration = sync_->belt_acceleration();
  }
  return true;
}

}  // namespace ncsim::channel

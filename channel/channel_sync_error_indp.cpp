// channel/channel_sync_error_indp: INDP axes owned when a run-time error comes while synchronised
// (seed 004 §2.3 l.492-498; trafo-feed, issue 14; docs/conveyor.md "Errors while
// synchronised", "With INDP axes").
//
// Decision: the manual's rule (the path velocity in PCS1 goes to 0, the machine follows the
// belt) speaks of the path. An INDP axis is "single-axis with the axis's own limits"
// (isg-language.md §6.1) and does not follow the belt: at the error its motion stops on its
// own deceleration ramp (IndpAxes::stop: plan_stop with the motion's A- and J, jerk-limited),
// while the path axes follow the belt and brake before their soft limits as without INDP axes
// (channel_sync_error.cpp). SyncErrorStop decides on the path axes only (the INDP axes enter
// it at rest); the run ends with the original error when the path axes and every INDP axis
// stand. Under #TRAFO ON an owned INDP axis is not built: the run ends at once as before.
// Decision: a command ncsim refused (NC6001 `not supported`, NC6104 an INDP motion that does
// not plan) ends the run at once: the interpreter's position of the axis is the target the
// motion never went to, so the path's next block would start there (a jump); nor can a run
// go on as the program meant after a construct ncsim does not model.

#include <cstddef>

#include "channel/channel.hpp"
#include "program/program_source.hpp"

namespace ncsim::ipo {

bool Channel::sync_error_indp_begin() noexcept {
  after_indp_ = 0;
  if (error_->id == kNotSupportedId || error_->id == kIndpPlanId) return false;  // decision
  for (std::size_t i = 0; i < axes_.size(); ++i)
    if (indp_.axes().owned(i)) after_indp_ |= planner::AxisMask{1} << i;
  if (after_indp_ == 0) return true;
  if (kin_.transformed()) {  // not built (docs/conveyor.md): the run ends with the error at once
    after_indp_ = 0;
    return false;
  }
  for (std::size_t i = 0; i < axes_.size(); ++i)
    if ((after_indp_ >> i) & 1u) (void)indp_.axes().stop(i);  // false: it stood already
  return true;
}

void Channel::sync_error_indp_step(const Cycle& c) noexcept {
  if (after_indp_ == 0) return;
  indp_.step_once(c);  // the error's own cycle may have stepped them already
  sync_error_indp_apply();
}

void Channel::sync_error_indp_apply() noexcept {
  if (after_indp_ == 0) return;
  after_cycle_.independent = after_indp_;
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    if (((after_indp_ >> i) & 1u) == 0) continue;
    const axes::Setpoint& sp = indp_.axes().setpoint(i);
    axes_.setpoints()[i] = sp;
    after_cycle_.x[i] = sp.p;
    after_cycle_.v[i] = sp.v;
    after_cycle_.a[i] = sp.a;
    after_cycle_.j[i] = sp.j;
  }
}

std::array<axes::Setpoint, planner::kMaxAxes> Channel::sync_error_path_axes() const noexcept {
  std::array<axes::Setpoint, planner::kMaxAxes> out{};
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    out[i] = axes_.setpoints()[i];
    if ((after_indp_ >> i) & 1u) out[i] = axes::Setpoint{axes_.setpoints()[i].p, 0.0, 0.0, 0.0};
  }
  return out;
}

bool Channel::sync_error_indp_stood() const noexcept {
  return after_indp_ == 0 || indp_.axes().in_position_mask(after_indp_);
}

}  // namespace ncsim::ipo

// channel/after_error_indp: the after-error stop with INDP axes owned when a run-time error comes
// while synchronised (seed 004 §2.3 l.492-498; trafo-feed, issue 14; docs/conveyor.md "Errors
// while synchronised", "With INDP axes").
//
// Decision: the manual's rule (the path velocity in PCS1 goes to 0, the machine follows the
// belt) speaks of the path. An INDP axis is "single-axis with the axis's own limits"
// (isg-language.md §6.1) and does not follow the belt: at the error its motion stops on its
// own deceleration ramp (IndpAxes::stop: plan_stop with the motion's A- and J, jerk-limited),
// while the path axes follow the belt and brake before their soft limits as without INDP axes
// (after_error.cpp). The axes' SyncErrorStop decides on the path axes only (the INDP axes enter
// it at rest); the run ends with the original error when the path axes and every INDP axis
// stand. Under #TRAFO ON an owned INDP axis is not built: the run ends at once as before.
// Decision: a command ncsim refused (NC6001 `not supported`, NC6104 an INDP motion that does
// not plan) ends the run at once: the interpreter's position of the axis is the target the
// motion never went to, so the path's next block would start there (a jump); nor can a run
// go on as the program meant after a construct ncsim does not model.

#include <cstddef>
#include <string>

#include "channel/after_error.hpp"
#include "program/program_source.hpp"

namespace ncsim::channel {

bool AfterErrorStop::begin_indp() noexcept {
  indp_mask_ = 0;
  if (error_->id == program::kNotSupportedId || error_->id == kIndpPlanId)
    return false;  // decision
  for (std::size_t i = 0; i < axes_.size(); ++i)
    if (indp_.axes().owned(i)) indp_mask_ |= planner::AxisMask{1} << i;
  if (indp_mask_ == 0) return true;
  if (kin_.transformed()) {  // not built (docs/conveyor.md): the run ends with the error at once
    indp_mask_ = 0;
    return false;
  }
  for (std::size_t i = 0; i < axes_.size(); ++i)
    if ((indp_mask_ >> i) & 1u) (void)indp_.axes().stop(i);  // false: it stood already
  return true;
}

void AfterErrorStop::step_indp(const ipo::Cycle& c) noexcept {
  if (indp_mask_ == 0) return;
  indp_.step_once(c);  // the error's own cycle may have stepped them already
  apply_indp();
}

void AfterErrorStop::apply_indp() noexcept {
  if (indp_mask_ == 0) return;
  cycle_.independent = indp_mask_;
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    if (((indp_mask_ >> i) & 1u) == 0) continue;
    const axes::Setpoint& sp = indp_.axes().setpoint(i);
    axes_.setpoints()[i] = sp;
    cycle_.x[i] = sp.p;
    cycle_.v[i] = sp.v;
    cycle_.a[i] = sp.a;
    cycle_.j[i] = sp.j;
  }
}

bool AfterErrorStop::indp_stood() const noexcept {
  return indp_mask_ == 0 || indp_.axes().in_position_mask(indp_mask_);
}

std::string AfterErrorStop::indp_note() const {
  std::string indp;
  for (std::size_t i = 0; i < axes_.size(); ++i)
    if ((indp_mask_ >> i) & 1u) indp += (indp.empty() ? "" : ", ") + axes_.config(i).name;
  if (!indp.empty()) indp = "; INDP axis " + indp + " braked on its own ramp";
  return indp;
}

}  // namespace ncsim::channel

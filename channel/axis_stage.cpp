// channel/axis_stage: the channel's interpolated axes (see the header).

#include "channel/axis_stage.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/number_text.hpp"

namespace ncsim::channel {

AxisStage::AxisStage(const std::vector<ChannelAxis>& axes, const planner::AxisVec& start,
                     double t_cycle) {
  axes_.reserve(axes.size());
  for (std::size_t i = 0; i < axes.size(); ++i) {
    const double p0 = start[i];
    const ChannelAxis& a = axes[i];
    try {
      axes_.push_back(Axis{a, axes::PositionControlModel(a.control, t_cycle, p0),
                           axes::AxisMonitor(a.monitor, t_cycle, static_cast<int>(i))});
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("axis " + a.name + ": " + e.what());
    }
    state_.command[i] = p0;
    state_.actual[i] = p0;
  }
}

std::size_t AxisStage::find(std::uint8_t machine_index) const noexcept {
  std::size_t i = 0;
  while (i < axes_.size() && axes_[i].config.indp.machine_index != machine_index)
    ++i;
  return i;
}

void AxisStage::control_step(std::size_t i) noexcept {
  const axes::ActualValue act = axes_[i].control.step(setpoint_[i]);
  state_.actual[i] = act.position;
  state_.following_error[i] = act.following_error;
  lag_max_[i] = std::max(lag_max_[i], std::fabs(act.following_error));
}

void AxisStage::follow(std::size_t i) noexcept {
  state_.command[i] = setpoint_[i].p;
  control_step(i);
}

bool AxisStage::drive(std::size_t i, const ipo::Cycle& c, bool motion_active, bool waiting,
                      double target, double waited, std::optional<RunTimeError>& error) noexcept {
  Axis& a = axes_[i];
  const axes::Setpoint& sp = setpoint_[i];
  const int axis = static_cast<int>(i);
  state_.command[i] = sp.p;
  // Soft limits P-AXIS-00177 / 00178 on the command position, every cycle: the axis never
  // receives a set position beyond them (an arc can cross a limit between its end points).
  if (const auto alarm = axes::check_soft_limits(a.config.monitor.soft_limits, sp.p, axis, c.t)) {
    const bool low = alarm->kind == axes::AlarmKind::soft_limit_min;
    raise(error, alarm->id.data(),
          "axis " + a.config.name + ": command position " + core::human(sp.p) +
              (low ? " mm below the minimum soft position limit "
                   : " mm above the maximum soft position limit ") +
              core::human(alarm->limit) + (low ? " mm (P-AXIS-00177)" : " mm (P-AXIS-00178)"),
          c, axis);
    return false;
  }
  control_step(i);
  axes::AxisSample s;
  s.t = c.t;
  s.command_position = sp.p;
  s.actual_position = state_.actual[i];
  s.motion_active = motion_active;
  if (waiting) s.target = target;
  const auto alarm = a.monitor.step(s);
  if (!alarm) return true;
  std::string what;
  switch (alarm->kind) {
    case axes::AlarmKind::position_lag:
      what = ": position lag " + core::human(alarm->value) + " mm above the maximum " +
             core::human(alarm->limit) +
             " mm for longer than the filter time (NCSIM-AXIS-025 / 026)";
      break;
    case axes::AlarmKind::exact_stop_timeout:
      what = ": exact stop window P-AXIS-00236 (" +
             core::human(a.config.monitor.exact_stop.window) +
             " mm) not reached within P-AXIS-00532 (" + core::human(alarm->limit) + " s), " +
             core::human(std::fabs(target - state_.actual[i])) + " mm from the target after " +
             core::human(waited) + " s";
      break;
    default:
      what = ": " + axes::describe(*alarm);
      break;
  }
  raise(error, alarm->id.data(), "axis " + a.config.name + what, c, axis);
  return false;
}

}  // namespace ncsim::channel

#pragma once
// channel/axis_stage: the channel's interpolated axes (step "drive the axes" of Channel::step).
//
// Purpose: each axis's setpoint of the cycle through the PTP axis core's position-control
// model (axes/control) and monitor (axes/monitor): soft limits P-AXIS-00177 / 00178 on the
// command position (NC5501 / NC5502), then the control step (actual position, following
// error), then the monitors (position lag 0x4550, exact-stop window P-ERR-70082, ...).
// Inputs: the ChannelAxis list and the start position; per cycle the setpoints (written by
// the mapping, the INDP axes, the after-error stop) and per axis whether it is in motion and
// the exact-stop target it waits for. Outputs: AxesState (command, actual, following error),
// the largest following error per axis, a RunTimeError on an alarm.
// Invariants: noexcept per cycle; no allocation per cycle (only when an alarm is reported).

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "axes/control.hpp"
#include "axes/monitor.hpp"
#include "channel/channel_types.hpp"

namespace ncsim::channel {

class AxisStage {
 public:
  /// Throws std::invalid_argument (axis named) on an unusable control or monitor parameter.
  AxisStage(const std::vector<ChannelAxis>& axes, const planner::AxisVec& start, double t_cycle);

  std::size_t size() const noexcept { return axes_.size(); }
  const ChannelAxis& config(std::size_t i) const noexcept { return axes_[i].config; }
  /// The setpoint (p, v, a, j) of every axis in the cycle being computed [mm | deg, /s ...].
  std::array<axes::Setpoint, planner::kMaxAxes>& setpoints() noexcept { return setpoint_; }
  const std::array<axes::Setpoint, planner::kMaxAxes>& setpoints() const noexcept {
    return setpoint_;
  }
  const AxesState& state() const noexcept { return state_; }
  /// Largest |following error| seen per axis so far [mm | deg].
  const planner::AxisVec& following_error_max() const noexcept { return lag_max_; }
  /// Axis i's actual position is inside its exact-stop window P-AXIS-00236.
  bool in_window(std::size_t i) const noexcept {
    return axes_[i].monitor.status().in_exact_stop_window;
  }
  /// The channel axis of machine axis `machine_index`; size() when none.
  std::size_t find(std::uint8_t machine_index) const noexcept;

  /// Drives axis i with its setpoint for cycle `c`: soft limits, control, monitor.
  /// `motion_active`: the monitor's motion flag; `waiting`: the axis waits at an exact stop
  /// for `target` [mm | deg], since `waited` [s] (messages). False: `error` raised.
  bool drive(std::size_t i, const ipo::Cycle& c, bool motion_active, bool waiting, double target,
             double waited, std::optional<RunTimeError>& error) noexcept;
  /// Axis i's control step alone (no limits, no monitor: the channel is in its error state).
  void follow(std::size_t i) noexcept;

 private:
  struct Axis {
    ChannelAxis config;
    axes::PositionControlModel control;
    axes::AxisMonitor monitor;
  };
  void control_step(std::size_t i) noexcept;

  std::vector<Axis> axes_;
  std::array<axes::Setpoint, planner::kMaxAxes> setpoint_{};
  AxesState state_;
  planner::AxisVec lag_max_{};
};

}  // namespace ncsim::channel

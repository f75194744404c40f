#include "axes/monitor.hpp"

#include <cmath>
#include <stdexcept>

#include "core/number_text.hpp"
#include "core/tolerance.hpp"

namespace ncsim::axes {
namespace {

void require_non_negative(const char* parameter, double value) {
  if (!std::isfinite(value) || value < 0.0) {
    throw std::invalid_argument(std::string("axis monitoring parameter ") + parameter + " = " +
                                core::number_text(value) + ": must be finite and >= 0");
  }
}

/// Cycles a condition may hold before "longer than `time`" is true: n * T > time.
std::int64_t cycles_allowed(double time, double t_cycle) {
  return static_cast<std::int64_t>(std::floor(time / t_cycle + kCycleRounding));
}

/// Cycles a condition must hold for "at least `time`": n * T >= time, at least one cycle.
std::int64_t cycles_needed(double time, double t_cycle) {
  const auto n = static_cast<std::int64_t>(std::ceil(time / t_cycle - kCycleRounding));
  return n < 1 ? 1 : n;
}

AxisAlarm make_alarm(AlarmKind kind, int axis, double t, double value, double limit) {
  AxisAlarm alarm;
  alarm.kind = kind;
  alarm.axis = axis;
  alarm.t = t;
  alarm.value = value;
  alarm.limit = limit;
  switch (kind) {
    case AlarmKind::soft_limit_min:
      alarm.id = kIdSoftLimitMin;
      alarm.reaction = AlarmReaction::reject_command;
      break;
    case AlarmKind::soft_limit_max:
      alarm.id = kIdSoftLimitMax;
      alarm.reaction = AlarmReaction::reject_command;
      break;
    case AlarmKind::position_lag:
      alarm.id = kIdPositionLag;
      alarm.reaction = AlarmReaction::shutdown;  // 000_* 7.1.5 "direct shutdown"
      break;
    case AlarmKind::in_target_timeout:
      alarm.id = kIdInTargetTimeout;
      alarm.reaction = AlarmReaction::shutdown;
      break;
    case AlarmKind::motion_not_detected:
      alarm.id = kIdMotionNotDetected;
      alarm.reaction = AlarmReaction::shutdown;
      break;
    case AlarmKind::exact_stop_timeout:
      alarm.id = kIdExactStopTimeout;
      alarm.reaction = AlarmReaction::stop;  // 001_* 2: stop the axis and its path partners
      break;
  }
  return alarm;
}

}  // namespace

std::string describe(const AxisAlarm& alarm) {
  const std::string value = core::human(alarm.value);
  const std::string limit = core::human(alarm.limit);
  std::string what;
  switch (alarm.kind) {
    case AlarmKind::soft_limit_min:
      what = "target position " + value + " mm lies below the minimum soft position limit " +
             limit + " mm";
      break;
    case AlarmKind::soft_limit_max:
      what = "target position " + value + " mm lies above the maximum soft position limit " +
             limit + " mm";
      break;
    case AlarmKind::position_lag:
      what = "position lag " + value + " mm exceeded the maximum position lag " + limit +
             " mm for longer than the filter time";
      break;
    case AlarmKind::in_target_timeout:
      what = "target position window not reached within the In-Target timeout (" + value + " s > " +
             limit + " s)";
      break;
    case AlarmKind::motion_not_detected:
      what = "no motion detected while a motion command was active (" + value + " s > " + limit +
             " s)";
      break;
    case AlarmKind::exact_stop_timeout:
      what = "exact stop window not reached within the position settling time (" + value + " s > " +
             limit + " s)";
      break;
  }
  return "axis " + std::to_string(alarm.axis) + " at t=" + core::decimals_text(alarm.t, 6) +
         " s: " + what;
}

core::Diagnostic to_diagnostic(const AxisAlarm& alarm) {
  core::Diagnostic diagnostic;
  diagnostic.severity = core::Severity::error;
  diagnostic.id = std::string(alarm.id);
  diagnostic.message = describe(alarm);
  return diagnostic;
}

std::optional<AxisAlarm> check_soft_limits(const SoftLimitParams& limits, double target, int axis,
                                           double t) {
  // Written so that a NaN target is rejected too.
  if (limits.min_enabled && !(target >= limits.min_position)) {
    return make_alarm(AlarmKind::soft_limit_min, axis, t, target, limits.min_position);
  }
  if (limits.max_enabled && !(target <= limits.max_position)) {
    return make_alarm(AlarmKind::soft_limit_max, axis, t, target, limits.max_position);
  }
  return std::nullopt;
}

double effective_settling_time(const ExactStopParams& params) {
  return params.settling_time >= 0.0 ? params.settling_time : params.legacy_settling_time;
}

AxisMonitor::AxisMonitor(const AxisMonitorParams& params, double t_cycle, int axis)
    : params_(params), t_cycle_(t_cycle), axis_(axis) {
  if (!std::isfinite(t_cycle) || t_cycle <= 0.0) {
    throw std::invalid_argument("axis monitoring: cycle time " + core::number_text(t_cycle) +
                                " s must be finite and > 0");
  }
  const SoftLimitParams& soft = params.soft_limits;
  if (soft.min_enabled && soft.max_enabled && soft.min_position > soft.max_position) {
    throw std::invalid_argument(
        "axis monitoring parameter Minimum Position (P-AXIS-00177) = " +
        core::number_text(soft.min_position) +
        " lies above Maximum Position (P-AXIS-00178) = " + core::number_text(soft.max_position));
  }
  require_non_negative("Maximum Position Lag Value [mm]", params.lag.max_lag);
  require_non_negative("Maximum Position Lag Filter Time [s]", params.lag.filter_time);
  require_non_negative("Position Range Window [mm]", params.position_range.window);
  require_non_negative("Target Position Window [mm]", params.target_position.window);
  require_non_negative("Target Position Monitoring Time [s]", params.target_position.time);
  require_non_negative("In-Target Timeout [s]", params.target_position.in_target_timeout);
  require_non_negative("Motion Monitoring Window [mm]", params.motion.window);
  require_non_negative("Motion Monitoring Time [s]", params.motion.time);
  require_non_negative("P-AXIS-00236 exact stop window [mm]", params.exact_stop.window);
  if (!std::isfinite(params.exact_stop.settling_time)) {
    throw std::invalid_argument("axis monitoring parameter P-AXIS-00532 = " +
                                core::number_text(params.exact_stop.settling_time) +
                                ": must be finite");
  }
  const double settling = effective_settling_time(params.exact_stop);
  require_non_negative("P-AXIS-00151 settling time [s] (used because P-AXIS-00532 < 0)", settling);

  lag_cycles_allowed_ = cycles_allowed(params.lag.filter_time, t_cycle);
  target_cycles_needed_ = cycles_needed(params.target_position.time, t_cycle);
  in_target_cycles_allowed_ = cycles_allowed(params.target_position.in_target_timeout, t_cycle);
  still_cycles_allowed_ = cycles_allowed(params.motion.time, t_cycle);
  if (settling > 0.0) settling_cycles_allowed_ = cycles_allowed(settling, t_cycle);
}

void AxisMonitor::start_positioning() noexcept {
  at_target_ = false;
  in_window_cycles_ = 0;
  since_target_cycles_ = 0;
  target_window_reached_ = false;
  exact_stop_reached_ = false;
  status_.in_target_position = false;
  status_.in_exact_stop_window = false;
}

void AxisMonitor::reset() noexcept {
  status_ = AxisMonitorStatus{};
  lag_cycles_ = 0;
  in_window_cycles_ = 0;
  since_target_cycles_ = 0;
  still_cycles_ = 0;
  at_target_ = false;
  target_window_reached_ = false;
  exact_stop_reached_ = false;
  target_.reset();
  last_actual_.reset();
}

std::optional<AxisAlarm> AxisMonitor::step(const AxisSample& sample) noexcept {
  const double actual = sample.actual_position;
  status_.following_error = sample.command_position - actual;  // 000_* 7.1.5

  // A new positioning starts when the target changes or a motion starts after the set
  // position had reached the old target.
  const bool target_changed = sample.target.has_value() != target_.has_value() ||
                              (sample.target && *sample.target != *target_);
  if (target_changed || (at_target_ && sample.motion_active)) start_positioning();
  target_ = sample.target;
  const bool was_at_target = at_target_;
  at_target_ = target_.has_value() && !sample.motion_active;
  if (at_target_ && was_at_target) ++since_target_cycles_;  // 0 in the cycle it arrives

  const double distance = target_ ? std::fabs(*target_ - actual) : 0.0;

  // Position range: status only.
  status_.in_position_area =
      params_.position_range.enabled && target_ && distance <= params_.position_range.window;

  std::optional<AxisAlarm> alarm;
  auto raise = [&](AlarmKind kind, double value, double limit) {
    if (!alarm) alarm = make_alarm(kind, axis_, sample.t, value, limit);
  };

  // Position lag (000_* 7.1.5): longer than the filter time above the limit.
  if (params_.lag.enabled && std::fabs(status_.following_error) > params_.lag.max_lag) {
    ++lag_cycles_;
    if (lag_cycles_ > lag_cycles_allowed_) {
      raise(AlarmKind::position_lag, status_.following_error, params_.lag.max_lag);
    }
  } else {
    lag_cycles_ = 0;
  }

  // Motion monitoring (000_* 7.1.5): during a motion command the actual position must move by
  // more than the window in at least one cycle of every monitoring time.
  if (params_.motion.enabled && sample.motion_active && last_actual_) {
    if (std::fabs(actual - *last_actual_) > params_.motion.window) {
      still_cycles_ = 0;
    } else {
      ++still_cycles_;
      if (still_cycles_ > still_cycles_allowed_) {
        raise(AlarmKind::motion_not_detected, static_cast<double>(still_cycles_) * t_cycle_,
              params_.motion.time);
      }
    }
  } else {
    still_cycles_ = 0;
  }
  last_actual_ = actual;

  // Target position monitoring and In-Target alarm (000_* 7.1.5).
  const TargetPositionParams& tp = params_.target_position;
  if (tp.enabled && at_target_) {
    const bool in_window = distance <= tp.window;
    in_window_cycles_ = in_window ? in_window_cycles_ + 1 : 0;
    status_.in_target_position = in_window_cycles_ >= target_cycles_needed_;
    if (in_window) target_window_reached_ = true;
    if (tp.in_target_alarm && !target_window_reached_ &&
        since_target_cycles_ > in_target_cycles_allowed_) {
      raise(AlarmKind::in_target_timeout, static_cast<double>(since_target_cycles_) * t_cycle_,
            tp.in_target_timeout);
    }
  } else {
    in_window_cycles_ = 0;
    status_.in_target_position = false;
  }

  // Exact stop window P-AXIS-00236 within P-AXIS-00532 (001_* 2).
  if (at_target_) {
    status_.in_exact_stop_window = distance <= params_.exact_stop.window;
    if (status_.in_exact_stop_window) exact_stop_reached_ = true;
    if (!exact_stop_reached_ && settling_cycles_allowed_ &&
        since_target_cycles_ > *settling_cycles_allowed_) {
      raise(AlarmKind::exact_stop_timeout, static_cast<double>(since_target_cycles_) * t_cycle_,
            effective_settling_time(params_.exact_stop));
    }
  } else {
    status_.in_exact_stop_window = false;
  }

  if (status_.error) return std::nullopt;
  if (alarm) status_.error = true;
  return alarm;
}

}  // namespace ncsim::axes

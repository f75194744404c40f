#pragma once
// axes/monitor: the monitors of one axis and the alarms they raise.
//
// Per cycle the channel hands each axis's command and actual value to AxisMonitor::step(),
// which updates the status flags and returns at most one alarm. Alarms are value types: the
// channel acts on them (stops the axis, stops the axes interpolated with it); nothing here
// stops anything. Before a motion starts, check_soft_limits() rejects targets beyond the soft
// position limits.
//
// Monitors (000_* 7.1.4 / 7.1.5, 001_* section 2):
//   soft limits        commands beyond Minimum/Maximum Position are rejected (7.1.4)
//   position lag       |set - actual| above Maximum Position Lag Value for longer than the
//                      Maximum Position Lag Filter Time -> 0x4550, direct shutdown (7.1.5)
//   position range     status In Position Area: |target - actual| <= window (7.1.5)
//   target position    status In Target Position: in the window without interruption for at
//                      least the monitoring time (7.1.5)
//   in-target alarm    the window is not reached within the In-Target Timeout, counted from
//                      the cycle the set position reaches the target -> 0x435C (7.1.5)
//   motion monitoring  while a motion command runs, the actual position must change by more
//                      than the window in at least one cycle of every Motion Monitoring Time
//                      -> 0x435D (7.1.5)
//   exact stop         the actual position must reach the window P-AXIS-00236 within
//                      P-AXIS-00532 after the set position reaches the target -> P-ERR-70082
//                      (001_* 2); reaching the window ends G60 / INDP_SYN motions.
//
// Timing rule (ncsim's, the manuals do not say how a time is counted in cycles): a cycle in
// which a condition holds counts as one full cycle T. "For longer than t" is n * T > t, "at
// least t" is n * T >= t; both are evaluated on integer cycle counts fixed at construction, so
// an alarm comes exactly in the cycle the limit is crossed, never a cycle early by rounding.
//
// Invariants: step() is noexcept and does not allocate; after an alarm the monitor is in the
// error state and reports nothing more until reset().

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/diagnostic.hpp"

namespace ncsim::axes {

enum class AlarmKind {
  soft_limit_min,       ///< target below Minimum Position (P-AXIS-00177)
  soft_limit_max,       ///< target above Maximum Position (P-AXIS-00178)
  position_lag,         ///< 0x4550
  in_target_timeout,    ///< 0x435C
  motion_not_detected,  ///< 0x435D
  exact_stop_timeout,   ///< P-ERR-70082
};

/// What the channel must do with an alarm.
enum class AlarmReaction {
  reject_command,  ///< the command is not started; nothing moves
  shutdown,        ///< axis stopped at once by direct shutdown, error state; the axes
                   ///< interpolated or coupled with it are stopped (000_* 7.1.5, 002_* 3.1)
  stop,            ///< axis stopped immediately, all axes interpolated with it in the path
                   ///< compound stopped (001_* section 2, reaction 1 and 2)
};

/// An alarm of one axis: what, where, when, and the numbers that broke the limit.
struct AxisAlarm {
  AlarmKind kind = AlarmKind::position_lag;
  std::string_view id;  ///< the manual's id ("0x4550", "P-ERR-70082") or ncsim's ("NC5501")
  AlarmReaction reaction = AlarmReaction::stop;
  int axis = 0;        ///< axis index in machine order
  double t = 0.0;      ///< [s] time of the cycle that raised it
  double value = 0.0;  ///< [mm] or [s] the value that broke the limit
  double limit = 0.0;  ///< [mm] or [s] the limit
};

/// One line of text: what happened, the value and the limit.
std::string describe(const AxisAlarm& alarm);
/// The alarm as a diagnostic (no file position: run-time alarms are not tied to a source line
/// here; the channel adds the block's location when it has one).
core::Diagnostic to_diagnostic(const AxisAlarm& alarm);

inline constexpr std::string_view kIdSoftLimitMin = "NC5501";
inline constexpr std::string_view kIdSoftLimitMax = "NC5502";
inline constexpr std::string_view kIdPositionLag = "0x4550";
inline constexpr std::string_view kIdInTargetTimeout = "0x435C";
inline constexpr std::string_view kIdMotionNotDetected = "0x435D";
inline constexpr std::string_view kIdExactStopTimeout = "P-ERR-70082";

/// Soft position limits (000_* 7.1.4; ISG P-AXIS-00177 kenngr.swe_neg, P-AXIS-00178
/// kenngr.swe_pos).
struct SoftLimitParams {
  bool min_enabled = false;   ///< "Soft Position Limit Minimum Monitoring"
  double min_position = 0.0;  ///< [mm] "Minimum Position" (P-AXIS-00177)
  bool max_enabled = false;   ///< "Soft Position Limit Maximum Monitoring"
  double max_position = 0.0;  ///< [mm] "Maximum Position" (P-AXIS-00178)
};

/// A command whose target lies beyond an enabled soft limit is rejected before it moves
/// (000_* 7.1.4 "Commands that violate this lower limit will be rejected"). A target exactly
/// on the limit is allowed.
std::optional<AxisAlarm> check_soft_limits(const SoftLimitParams& limits, double target, int axis,
                                           double t);

/// Position lag monitoring (000_* 7.1.5 / 7.4.1).
struct LagMonitorParams {
  bool enabled = true;        ///< "Position Lag Monitoring"
  double max_lag = 5.0;       ///< [mm] "Maximum Position Lag Value"
  double filter_time = 0.02;  ///< [s] "Maximum Position Lag Filter Time"
};

/// Position range monitoring (000_* 7.1.5): status flag only.
struct PositionRangeParams {
  bool enabled = true;  ///< "Position Range Monitoring"
  double window = 5.0;  ///< [mm] "Position Range Window" (half width)
};

/// Target position monitoring and In-Target alarm (000_* 7.1.5).
struct TargetPositionParams {
  bool enabled = true;             ///< "Target Position Monitoring"
  double window = 2.0;             ///< [mm] "Target Position Window" (half width)
  double time = 0.02;              ///< [s] "Target Position Monitoring Time"
  bool in_target_alarm = false;    ///< "In-Target Alarm"
  double in_target_timeout = 5.0;  ///< [s] "In-Target Timeout"
};

/// Motion monitoring (000_* 7.1.5).
struct MotionMonitorParams {
  bool enabled = false;  ///< "Motion Monitoring"
  double window = 0.0;   ///< [mm] "Motion Monitoring Window": expected travel per cycle
  double time = 0.5;     ///< [s] "Motion Monitoring Time"
};

/// Exact stop window and settling time (001_* section 3.2).
struct ExactStopParams {
  double window = 0.05;          ///< [mm] P-AXIS-00236 getriebe[i].window (default 500 x 0.1 um)
  double settling_time = -1e-6;  ///< [s] P-AXIS-00532 getriebe[i].position_settling_time
                                 ///< (default -1 us): 0 disables, < 0 uses legacy_settling_time
  double legacy_settling_time = 0.0;  ///< [s] P-AXIS-00151, used when P-AXIS-00532 < 0
};

struct AxisMonitorParams {
  SoftLimitParams soft_limits;
  LagMonitorParams lag;
  PositionRangeParams position_range;
  TargetPositionParams target_position;
  MotionMonitorParams motion;
  ExactStopParams exact_stop;
};

/// The time P-AXIS-00532 stands for: itself when >= 0 (0 = no time monitoring), else
/// P-AXIS-00151 (001_* 3.2, "backward compatibility").
double effective_settling_time(const ExactStopParams& params);

/// What the monitors see of an axis in one cycle.
struct AxisSample {
  double t = 0.0;                 ///< [s] time of this cycle
  double command_position = 0.0;  ///< [mm] set position
  double actual_position = 0.0;   ///< [mm] actual position
  bool motion_active = false;     ///< a motion command is executing (not at logical standstill)
  std::optional<double> target;   ///< [mm] target of the current or last positioning; none for
                                  ///< velocity motions, couplings and before the first move
};

/// Status of the monitors after a cycle.
struct AxisMonitorStatus {
  double following_error = 0.0;       ///< [mm] set position - actual position (000_* 7.1.5)
  bool in_position_area = false;      ///< Axis.Status.InPositionArea
  bool in_target_position = false;    ///< Axis.Status.InTargetPosition
  bool in_exact_stop_window = false;  ///< actual inside P-AXIS-00236 after the set position
                                      ///< reached the target (ends G60 / INDP_SYN)
  bool error = false;                 ///< an alarm was raised; reset() clears it
};

class AxisMonitor {
 public:
  /// Throws std::invalid_argument naming the parameter for negative windows or times,
  /// a non-positive cycle time, or min > max with both soft limits enabled.
  AxisMonitor(const AxisMonitorParams& params, double t_cycle, int axis);

  /// Runs every monitor for one cycle. Returns the alarm raised in this cycle, if any; when
  /// several trip together the first of lag, motion, in-target, exact stop is returned.
  std::optional<AxisAlarm> step(const AxisSample& sample) noexcept;

  const AxisMonitorStatus& status() const noexcept { return status_; }
  const AxisMonitorParams& params() const noexcept { return params_; }

  /// Before a new motion: rejects a target beyond the soft limits.
  std::optional<AxisAlarm> check_target(double target, double t) const {
    return check_soft_limits(params_.soft_limits, target, axis_, t);
  }

  /// Leaves the error state and forgets all timers (reset of the controller, 001_* 2).
  void reset() noexcept;

 private:
  void start_positioning() noexcept;

  AxisMonitorParams params_;
  double t_cycle_ = 0.0;  // [s]
  int axis_ = 0;
  // Cycle-count limits, fixed at construction (see the timing rule above).
  std::int64_t lag_cycles_allowed_ = 0;    // lag may exceed for this many cycles
  std::int64_t target_cycles_needed_ = 0;  // cycles in window for In Target Position
  std::int64_t in_target_cycles_allowed_ = 0;
  std::int64_t still_cycles_allowed_ = 0;
  std::optional<std::int64_t> settling_cycles_allowed_;  // none: no time monitoring
  // Running state.
  AxisMonitorStatus status_;
  std::int64_t lag_cycles_ = 0;
  std::int64_t in_window_cycles_ = 0;
  std::int64_t since_target_cycles_ = 0;  // cycles since the set position reached the target
  std::int64_t still_cycles_ = 0;
  bool at_target_ = false;  // set position has reached the target
  bool target_window_reached_ = false;
  bool exact_stop_reached_ = false;
  std::optional<double> target_;
  std::optional<double> last_actual_;
};

}  // namespace ncsim::axes

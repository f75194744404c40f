#pragma once
// tracking/sync_error: what the machine does after a run-time error raised while it is synchronised
// with the conveyor (seed 004 §2.3 l.492-498; docs/conveyor.md "Errors while synchronised").
//
// Purpose: the manual keeps the synchronisation after an error: the path velocity in PCS1 goes
// to 0, the machine moves on with the belt "until the limit switch position is reached", and a
// belt the PLC stops stops the machine with it. The channel brakes the path with its feed hold
// (a jerk-limited replan to 0 on the path, ipo/override) and keeps adding the PCS1 offset; this
// class decides, per cycle, when the axes must leave the belt so that none passes its software
// limit (P-AXIS-00177 / 00178) and then brakes each axis from its state to rest.
// Inputs: per axis its soft limits and its dynamics (the channel's feed limits, the tighter of
// feed and G00 slope, so that the audit's limits hold), the cycle T; per cycle the setpoints
// (p, v, a) the axes would get by following the belt.
// Outputs: must_stop() (brake now), then per cycle the braking setpoints; stood() when every
// axis is at rest.
// Decision (docs/conveyor.md): the axes brake when a jerk-limited stop from the state one cycle
// ahead (the axis's d_max and j_max) would end beyond its soft limit in its direction of motion,
// or when following would take it above v_max; all axes brake together, each with its own
// ramp, so the machine stops at once and before the limit. An axis without an enabled soft
// limit ahead has no "limit switch position": following ends after kFollowMax.
// Invariants: pure arithmetic on the inputs, no allocation, never throws.

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

#include "axes/control.hpp"
#include "axes/monitor.hpp"
#include "jerk/jerk.hpp"
#include "planner/move.hpp"

namespace ncsim::tracking {

/// One axis as the stop after an error sees it.
struct AfterErrorAxis {
  axes::SoftLimitParams soft;  ///< P-AXIS-00177 / 00178 and whether they are monitored
  double v_max = 0.0;          ///< [mm/s]
  double a_max = 0.0;          ///< A+ [mm/s^2]
  double d_max = 0.0;          ///< |A-| [mm/s^2]
  double j_max = 0.0;          ///< [mm/s^3]
};

/// The axis limits the audit holds an axis to, both slopes: the tighter of the feed limits and
/// planner::rapid_limits (an after-error cycle may carry either slope's flag).
AfterErrorAxis after_error_axis(const planner::AxisLimits& limits,
                                const axes::SoftLimitParams& soft) noexcept;

/// Why the machine came to rest after the error.
enum class AfterErrorEnd : std::uint8_t {
  soft_limit,  ///< the axes braked before a soft limit
  velocity,    ///< following the belt would have taken an axis above its v_max
  belt_stop,   ///< the belt stood (the PLC / scenario stopped it): the machine stood with it
  time_limit,  ///< no soft limit ahead: ncsim stopped following after kFollowMax
};

class SyncErrorStop {
 public:
  /// The longest an after-error motion follows the belt without a soft limit ahead [s].
  static constexpr double kFollowMax = 600.0;
  /// Below this the belt and the path count as standing [mm/s].
  static constexpr double kStandstill = 1e-6;

  /// True for the errors after which the synchronisation is kept: every run-time error except
  /// a soft limit (NC5501 / NC5502): an axis at its limit cannot follow the belt any more.
  static bool keeps_synchronisation(std::string_view id) noexcept;

  /// Per axis (interpolated order) and the cycle T [s]. A jerk that is not finite and > 0 (a
  /// STEP slope's) is taken as d_max / T (the deceleration built up in one cycle). False when
  /// an axis's v, a or d is not finite and > 0: the stop cannot be planned (usable() false).
  bool configure(std::span<const AfterErrorAxis> axes, double t_cycle) noexcept;
  /// configure() succeeded.
  bool usable() const noexcept { return usable_; }

  /// Follow the belt from now (the error's cycle): clears any earlier stop.
  void begin() noexcept;
  /// True when, given the setpoints `sp` of the cycle just computed (the belt followed), the
  /// axes must brake from it: a stop one cycle later would pass a soft limit or an axis would
  /// exceed v_max; also after kFollowMax of following. `why` and `axis` (-1: none) say which.
  bool must_stop(std::span<const axes::Setpoint> sp, AfterErrorEnd& why, int& axis) const noexcept;
  /// Starts the braking of every axis from `sp` (the last cycle's setpoints).
  void start_stopping(std::span<const axes::Setpoint> sp, AfterErrorEnd why, int axis) noexcept;
  /// The braking setpoints of the next cycle into `sp` (after start_stopping()).
  void step(std::span<axes::Setpoint> sp) noexcept;
  /// Counts one cycle of following (kFollowMax).
  void follow_cycle() noexcept { followed_ += t_cycle_; }

  bool stopping() const noexcept { return stopping_; }
  /// True once every braking ramp has ended (all axes at rest).
  bool stood() const noexcept { return stopping_ && elapsed_ >= duration_; }
  AfterErrorEnd why() const noexcept { return why_; }
  /// The axis whose limit decided the stop (-1: none, e.g. kFollowMax).
  int axis() const noexcept { return axis_; }
  /// Time the machine followed the belt before it braked [s].
  double followed() const noexcept { return followed_; }
  const AfterErrorAxis& limits(std::size_t i) const noexcept { return axes_[i]; }

 private:
  /// The stop of one axis from (p, v, a), in its direction of motion.
  struct Brake {
    jerk::State from;  ///< state at the start, in the direction of motion
    double dir = 1.0;  ///< +1 / -1
    jerk::Ramp ramp;
  };
  /// The state of `b` at time `t` after its start (MCS, signed).
  static axes::Setpoint at(const Brake& b, double t) noexcept;

  std::array<AfterErrorAxis, planner::kMaxAxes> axes_{};
  std::size_t n_ = 0;
  double t_cycle_ = 0.001;
  std::array<Brake, planner::kMaxAxes> brake_{};
  bool stopping_ = false;
  double elapsed_ = 0.0;   ///< since start_stopping [s]
  double duration_ = 0.0;  ///< the longest ramp [s]
  double followed_ = 0.0;  ///< [s]
  AfterErrorEnd why_ = AfterErrorEnd::soft_limit;
  int axis_ = -1;
  bool usable_ = false;
};

}  // namespace ncsim::tracking

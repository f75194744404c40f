#pragma once
// channel/indp_axes: the independent (INDP) axes of the channel, one PTP profile per axis, sampled
// every interpolation cycle (issue 12, isg-language.md §6.1).
//
// Purpose: X[INDP_SYN ...] / X[INDP_ASYN ...] move one axis on its own, outside the path's
// look-ahead, "single-axis with the axis's own limits" (isg-language.md §6.1 [I]). Each command
// becomes a jerk-limited PTP profile of the axis core (axes::plan_position with the axis's
// profile rule NCSIM-AXIS-030; TIME= through axes::plan_position_of_duration), planned from the
// axis's command state at the start of the cycle the command arrives in; step() advances every
// profile by one cycle T. A command to a moving axis replans from its moving state (v, a kept
// continuous; the manual's rule stops and returns when the axis cannot stop before the new
// target, 002_* 2.3).
// Inputs: one IndpAxisConfig per channel axis (the G01 and G00 dynamics, P-AXIS-00212, the soft
// limits P-AXIS-00177/00178, the profile rule and the override type), the cycle T, the start
// positions; then commands (command(), set_override(), interrupt()) and step() once per cycle.
// Outputs: per axis the setpoint (p, v, a, j) after the last step, whether the INDP layer owns
// the axis (owned(): the channel then drives the axis with this setpoint instead of the path's),
// whether its motion is done (in_position(): the command value reached the target, the
// condition of INDP_SYN and #WAIT INDP, isg-language.md §6.1 "waits until axis Z's command value
// reaches its target").
// Decisions (docs/ipo.md "INDP axes and technology functions"):
//  - G01 FEED: V = FEED, capped at P-AXIS-00212 (as the path caps F); the slope is the axis's
//    G01 slope A+ = min(P-AXIS-00001, P-AXIS-00008), A- = min(P-AXIS-00002, P-AXIS-00008),
//    J = the feed jerk, the limits the path and the audit use.
//  - G00: V = P-AXIS-00209 (capped at P-AXIS-00212), slope the smaller of the G01 and the G00
//    slope per quantity, so the audit's limit of any cycle holds whatever the path does then.
//  - TIME=t: the G01 slope with V = P-AXIS-00212 and the cruise level lowered so the motion
//    takes exactly t (plan_position_of_duration); a t shorter than the fastest profile runs the
//    fastest profile (the axis cannot do better; counted in capped()); so does a TIME that no
//    single-peak profile meets from the axis's moving state (axes' NC5015).
//  - Targets beyond an enabled soft limit are rejected before the axis moves (000_* 7.1.4,
//    seed-reading E12) with the soft limit's id NC5501 / NC5502.
//  - Override per axis (scenario [[event]] axis override, 002_* 2.2, seed-reading E10): 0..1;
//    the reference is the level activated at start ("Reduced (iterated)") or the commanded V
//    ("Original (iterated)") as the axis's override type says; an unreachable level is lowered
//    to the best reachable (iterated); a change takes effect at once only when no stop is
//    active and the braking phase (Profile::t_brake) is not reached, else it is kept and
//    applies from the axis's next command or its next override change; 0 stops on the axis's
//    deceleration ramp and holds, the target kept ("Stop wird über Override 0.0 verwirklicht").
//    An axis may start with override 0 (002_* 2.2): it holds until the override rises.
//  - interrupt(axis): the hook conveyor tracking calls at the next #SYNC IN for an INDP_SYN
//    motion programmed INTERRUPTIBLE: the axis stops at once on its deceleration ramp (the
//    fastest stop, plan_stop) and its motion counts as done where it stops. INDP_ASYN with
//    INTERRUPTIBLE is not interruptible (the syntax note, isg-language.md §6.1 / §5.13).
// Invariants: step() and every command never throw and never allocate; setpoints are
// continuous in p, v, a (every replan starts from the command state); deterministic.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "axes/monitor.hpp"
#include "axes/profile.hpp"
#include "axes/profile_generator.hpp"
#include "machines/machine.hpp"
#include "planner/move.hpp"

namespace ncsim::channel {

/// NC6104: the PTP core could not plan an INDP motion (the axes' Result id in the message).
inline constexpr const char* kIndpPlanId = "NC6104";

/// What the INDP layer needs of one channel axis.
struct IndpAxisConfig {
  std::string name;                ///< axis name (messages)
  std::uint8_t machine_index = 0;  ///< index in machines::Machine::axes (the commands\' axis)
  axes::Dynamics feed;             ///< G01: v_max = P-AXIS-00212, A+, A-, J [mm/s, mm/s^2, mm/s^3]
  axes::Dynamics rapid;            ///< G00: v_max = P-AXIS-00209, slope (decisions above)
  double increment = 1e-4;         ///< moves shorter than this do not start [mm | deg] (002_* 2.1)
  axes::SoftLimitParams limits;    ///< P-AXIS-00177 / 00178
  axes::ProfileRule rule = axes::ProfileRule::manual;  ///< NCSIM-AXIS-030
  axes::OverrideType override_type = axes::OverrideType::reduced_iterated;
};

/// The INDP configuration of machine axis `axis` (decisions above).
IndpAxisConfig indp_axis_config(const machines::AxisParams& axis);

/// One X[INDP_SYN ...] / X[INDP_ASYN ...] in internal units.
struct IndpMove {
  double target = 0.0;         ///< absolute POS [mm | deg]
  bool rapid = false;          ///< G00
  std::optional<double> feed;  ///< FEED [mm/s]
  std::optional<double> time;  ///< TIME [s]
  bool interruptible = false;  ///< INTERRUPTIBLE on an INDP_SYN motion
};

/// Why a command was refused.
struct IndpError {
  std::string id;       ///< NC5501 / NC5502 (soft limit), NC6104 (planning)
  std::string message;  ///< with the axis, the value and the limit
};

class IndpAxes {
 public:
  /// `axes` one per channel axis (channel order), `start` their positions [mm | deg], `t_cycle`
  /// [s]. Throws std::invalid_argument when t_cycle is not > 0 or there are more than
  /// planner::kMaxAxes axes. Unusable dynamics refuse the axis's commands (NC6104 naming the
  /// axes' NC5001), so a channel whose axes never move independently need not configure them.
  IndpAxes(std::vector<IndpAxisConfig> axes, double t_cycle, const planner::AxisVec& start);

  /// Starts (or replans) an INDP motion of axis `i` from its command state now (the start of
  /// the coming cycle). From here on the axis is owned by the INDP layer. A move shorter than
  /// the increment does nothing (002_* 2.1) but the axis is owned.
  std::optional<IndpError> command(std::size_t i, const IndpMove& move) noexcept;
  /// Override of axis `i` in [0, 1] (decisions above); ignored_braking_phase / rejected_stopping
  /// when it is kept for later; error_invalid_input outside [0, 1].
  axes::Result set_override(std::size_t i, double fraction) noexcept;
  /// Stops an INTERRUPTIBLE INDP_SYN motion of axis `i` on its fastest ramp (conveyor tracking
  /// calls it at the next #SYNC IN). True when a motion was interrupted.
  bool interrupt(std::size_t i) noexcept;
  /// True when axis `i` runs an INTERRUPTIBLE INDP_SYN motion.
  bool interruptible(std::size_t i) const noexcept;
  // An error while synchronised (004 §2.3, docs/conveyor.md).
  /// Stops the motion of axis `i`, whatever it is, on its deceleration ramp (the fastest stop
  /// with the motion's own A- and J, plan_stop); the motion counts as done where it stops.
  /// False when the axis runs none (in position).
  bool stop(std::size_t i) noexcept;

  /// Advances every owned axis by one cycle T.
  void step() noexcept;

  std::size_t size() const noexcept { return axes_.size(); }
  /// True when the INDP layer drives axis `i` (from its first command until release()).
  bool owned(std::size_t i) const noexcept { return axes_[i].owned; }
  /// Bit i: axis i is owned.
  planner::AxisMask owned_mask() const noexcept;
  /// The command value reached the target (or a stop ended the motion): no motion pending.
  bool in_position(std::size_t i) const noexcept { return axes_[i].mode == Mode::idle; }
  /// True when every axis of `mask` (bit i: axis i; 0: all) is in position.
  bool in_position_mask(planner::AxisMask mask) const noexcept;
  /// Axis `i`, not owned, is at `sp` (the path's setpoint of this cycle): an INDP command starts
  /// from there. No effect on an owned axis.
  void follow(std::size_t i, const axes::Setpoint& sp) noexcept {
    if (!axes_[i].owned) {
      axes_[i].sp = sp;
      axes_[i].target = sp.p;
    }
  }
  /// Hands axis `i` back to the path (it must be in position). Its setpoint stays as it is.
  void release(std::size_t i) noexcept { axes_[i].owned = false; }
  // The on-the-fly change (004 l.277-279).
  /// Ends the INTERRUPTIBLE INDP_SYN motion of axis `i` where it is, moving, and hands the axis
  /// to a motion that starts from its state (the catch-up after the next #SYNC IN). True when
  /// a motion was handed over; false (nothing changed) when the axis runs none.
  bool hand_over(std::size_t i) noexcept;
  /// Setpoint of axis `i` after the last step() [mm | deg, /s, /s^2, /s^3].
  const axes::Setpoint& setpoint(std::size_t i) const noexcept { return axes_[i].sp; }
  /// The axis's INDP target [mm | deg].
  double target(std::size_t i) const noexcept { return axes_[i].target; }
  /// Override in force for axis `i` [-].
  double override_fraction(std::size_t i) const noexcept { return axes_[i].override_; }
  /// Commands whose FEED or TIME the axis could not follow (capped at its limits).
  std::uint64_t capped() const noexcept { return capped_; }
  const IndpAxisConfig& config(std::size_t i) const noexcept { return axes_[i].config; }

 private:
  enum class Mode : std::uint8_t { idle, moving, held, stopping };
  struct Axis {
    IndpAxisConfig config;
    bool owned = false;
    Mode mode = Mode::idle;
    axes::Profile profile;
    std::uint64_t k = 0;      // cycles since the profile started
    double t = 0.0;           // k * T [s]
    double target = 0.0;      // [mm | deg]
    axes::Dynamics dynamics;  // of the motion (v_max: the commanded level)
    double v_level = 0.0;     // level activated at start at 100 % [mm/s]
    double override_ = 1.0;   // [-]
    bool interruptible = false;
    axes::Setpoint sp;
  };
  axes::MotionState state(const Axis& a) const noexcept;
  /// Plans the motion of `a` to its target at the override in force from its state now.
  axes::Result replan(Axis& a) noexcept;
  /// Sets mode and profile from a freshly planned profile.
  void take(Axis& a, const axes::Profile& p) noexcept;

  std::vector<Axis> axes_;
  double t_cycle_ = 0.0;
  std::uint64_t capped_ = 0;
};

}  // namespace ncsim::channel

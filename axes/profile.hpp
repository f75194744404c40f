#pragma once
// axes/profile: the jerk-limited PTP setpoint profile (TwinCAT NC PTP "Laufzeittabelle").
//
// Purpose: plan one single-axis motion as a chain of constant-jerk phases, the 7-phase profile
// of seed 002_* section 2.1 (jerk +J, [a = A+], jerk -J, [v = V], jerk -J, [a = -A-], jerk +J),
// from any start state (position, velocity, acceleration), to a target position reached at
// rest or at a given velocity with zero acceleration, or to a target velocity (endless motion,
// MC_MoveVelocity).
// Inputs: a MotionState, a target, Dynamics (V, A+, A-, J; path quantities as in 002_* 2.1:
// A+ limits speeding up, A- limits slowing down, whatever the sign of the axis velocity).
// Outputs: a Profile, a small value type; Profile::at(t) gives position, velocity,
// acceleration and jerk in closed form (a cubic per phase). Nothing integrates it.
// Invariants: phases are contiguous in time and state; |jerk| == J (or 0) in every phase;
// at(t) for t >= duration() is the end state, continued at constant velocity (zero for
// position targets reached at rest). Planning never throws and never allocates: it returns a
// Result (Ruckig style). Which rule applies where the manual is silent: docs/axes-profile.md.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "jerk/jerk.hpp"

namespace ncsim::axes {

namespace detail {
class ProfileBuilder;
}

/// Outcome of a planning call or of one cycle; never an exception on the cyclic path.
enum class Result : std::uint8_t {
  ok,                            ///< request accepted, profile computed
  working,                       ///< step(): motion in progress
  finished,                      ///< step(): target (position or velocity) reached
  error_invalid_input,           ///< NaN, non-positive limit, target velocity above V [NC5001]
  error_velocity_limit,          ///< requested velocity above the axis maximum [NC5002]
  ignored_braking_phase,         ///< override/compensation stop in a braking phase [NC5010]
  rejected_stopping,             ///< a stop is active and has priority [NC5011]
  rejected_compensation_active,  ///< new end position during compensation [NC5012]
  rejected_not_moving,           ///< online change needs a started axis [NC5013]
  ignored_below_increment,       ///< distance below one encoder increment: no start [NC5014]
  error_not_synchronizable,      ///< no single-peak profile of the required duration [NC5015]
};

/// ncsim diagnostic id ("NC5001") of a non-ok Result; empty for ok/working/finished.
std::string_view diagnostic_id(Result result) noexcept;
/// One-line English description of a Result.
std::string_view describe(Result result) noexcept;

/// Global dynamic parameters of one motion (002_* 2.1, Tab. 1/2): the jerk kernel's Limits
/// (v_max = V [mm/s], a_max = A+ and d_max = A- [mm/s^2], j_max = J [mm/s^3]), one struct for
/// the axes, the planner and the kernel.
using Dynamics = jerk::Limits;

/// True when every value is finite and > 0.
using jerk::valid;

/// Critical jerk (002_* 2.1): the J at which A+ and A- are just reached at velocity V,
/// max(A+, A-)^2 / V [mm/s^3].
double critical_jerk(const Dynamics& dynamics) noexcept;

/// Jerk rescaling (002_* 2.1 "Ruck ... automatisch reskaliert"): when a jerk phase to the
/// smaller acceleration limit would be shorter than t_cycle, J is lowered so that it lasts one
/// cycle. Returns the dynamics unchanged otherwise.
Dynamics rescale_jerk(const Dynamics& dynamics, double t_cycle) noexcept;

/// State of an axis at one instant (position [mm], velocity [mm/s], acceleration [mm/s^2]).
using MotionState = jerk::State;

/// Command values of one instant (what the position controller receives).
struct Setpoint {
  double p = 0.0;  ///< position [mm]
  double v = 0.0;  ///< velocity [mm/s]
  double a = 0.0;  ///< acceleration [mm/s^2]
  double j = 0.0;  ///< jerk [mm/s^3]
};

/// One constant-jerk phase: the state at its start and its jerk.
struct Phase {
  double t_start = 0.0;   ///< start time since profile start [s]
  double duration = 0.0;  ///< [s], >= 0
  double p = 0.0;         ///< position at t_start [mm]
  double v = 0.0;         ///< velocity at t_start [mm/s]
  double a = 0.0;         ///< acceleration at t_start [mm/s^2]
  double j = 0.0;         ///< jerk, constant in the phase [mm/s^3]
};

/// A planned motion: a value type, cheap to copy, no heap.
class Profile {
 public:
  static constexpr std::size_t kMaxPhases = 16;

  /// The axis standing still at `state.p` (velocity and acceleration ignored).
  static Profile at_rest(double p) noexcept;

  /// Command values at time t [s] since profile start; t < 0 gives the start state, t beyond
  /// duration() the end state continued at constant velocity.
  Setpoint at(double t) const noexcept;

  double duration() const noexcept { return duration_; }  ///< [s]
  /// Start of the braking phase (002_* 2.2), i.e. of the last velocity change [s].
  double t_brake() const noexcept { return t_brake_; }
  /// Velocity level activated by the planner (V, or the reduced reachable level) [mm/s].
  double v_level() const noexcept { return v_level_; }
  MotionState start_state() const noexcept { return start_; }
  MotionState end_state() const noexcept { return end_; }
  std::span<const Phase> phases() const noexcept { return {phases_.data(), count_}; }

 private:
  friend class detail::ProfileBuilder;
  std::array<Phase, kMaxPhases> phases_{};
  std::size_t count_ = 0;
  double duration_ = 0.0;
  double t_brake_ = 0.0;
  double v_level_ = 0.0;
  MotionState start_;
  MotionState end_;
};

/// Where a position motion ends.
struct PositionTarget {
  double p = 0.0;  ///< target position [mm]
  double v = 0.0;  ///< velocity at the target [mm/s], signed, |v| <= V; acceleration there is 0
};

/// Which rule shapes a position motion where the manual has one (docs/axes-profile.md,
/// "Profile rule"; ncsim axis parameter NCSIM-AXIS-030 `ncsim.profile_rule`, default manual).
enum class ProfileRule : std::uint8_t {
  manual,        ///< 002_* 2.1 symmetric min(A+, A-) when V is unreachable; 2.3 stop-and-return
  time_optimal,  ///< the fastest single-peak profile under the real A+, A- (reversal without stop)
};

/// Plans from `start` to `target` under `dynamics` (002_* 2.1). With ProfileRule::manual,
/// rest-to-rest moves follow the manual's rule for an unreachable V (highest velocity reachable
/// with the symmetric min(A+, A-)); starts that move away from or cannot stop before the target
/// stop first and return (002_* 2.3); start states beyond the limits are first brought back
/// inside them. ProfileRule::time_optimal plans the fastest single-peak profile instead
/// (jerk::fastest_move), falling back to the manual rule where that family does not apply.
Result plan_position(const MotionState& start, const PositionTarget& target,
                     const Dynamics& dynamics, Profile& out,
                     ProfileRule rule = ProfileRule::manual) noexcept;

/// Plans a profile from `start` to `target` taking exactly `duration` [s] (>= the motion's
/// own minimum): the cruise level is lowered (jerk::move_of_duration, in the reversed frame for
/// an overshoot), else the turning level of a turn to the arrival velocity
/// (jerk::reversal_of_duration), else the dip of a two-peak change, else the axis rests on the
/// way (at the target, or after a stop: docs/axes-profile.md). Returns error_not_synchronizable
/// [NC5015] when no family has a profile of that duration (a gap: see next_feasible_duration).
Result plan_position_of_duration(const MotionState& start, const PositionTarget& target,
                                 const Dynamics& dynamics, double duration, Profile& out) noexcept;

/// Where the durations of plan_position_of_duration resume after a gap: the shortest start of
/// a stretchable range beyond `duration` [s] (the single-peak family's lower range, the fastest
/// turn to an arrival velocity), negative when none is known. A moving start can have a gap:
/// too fast to dip much within the distance, and a turn takes far longer.
double next_feasible_duration(const MotionState& start, const PositionTarget& target,
                              const Dynamics& dynamics, double duration) noexcept;

/// Time-synchronised multi-axis motion (catch-up "all axes at once", INDP TIME=): each axis is
/// first planned alone under `rule`; every axis then gets a profile of exactly the longest
/// duration, or of `min_duration` [s] when that is longer (TIME=); where an axis has no profile
/// of that duration (a gap), the common duration moves to next_feasible_duration. All spans
/// have one size.
Result plan_synchronized(std::span<const MotionState> starts,
                         std::span<const PositionTarget> targets,
                         std::span<const Dynamics> dynamics, ProfileRule rule, double min_duration,
                         std::span<Profile> out) noexcept;

/// A target moving with constant velocity: p1 + v1 t (t [s] from now). Plans the earliest
/// meeting in position, velocity (v1) and acceleration (0) (single-peak profiles, turns);
/// `t_meet` receives the meeting time [s] (the profile's duration).
Result plan_moving_target(const MotionState& start, double p1, double v1, const Dynamics& dynamics,
                          Profile& out, double& t_meet) noexcept;
/// As above, meeting the target's position with velocity `v_arrive` [mm/s] instead of v1
/// (|v_arrive| <= V): the conveyor catch-up's relative velocity FEED_CONT (tracking/catch_up).
Result plan_moving_target(const MotionState& start, double p1, double v1, double v_arrive,
                          const Dynamics& dynamics, Profile& out, double& t_meet) noexcept;

/// Plans from `start` to the signed velocity `v_target` [mm/s] and constant velocity after it
/// (endless motion). A sign change stops first (A-), then speeds up the other way (A+).
/// dynamics.v_max is not used.
Result plan_velocity(const MotionState& start, double v_target, const Dynamics& dynamics,
                     Profile& out) noexcept;

/// Plans the fastest stop to rest from `start` (velocity change to zero, 002_* 2.2 "Stop").
Result plan_stop(const MotionState& start, const Dynamics& dynamics, Profile& out) noexcept;

}  // namespace ncsim::axes

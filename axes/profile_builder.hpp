#pragma once
// axes/profile_builder: internal building blocks of the planners in profile_*.cpp (not part of
// the public API). A ProfileBuilder appends constant-jerk phases to a Profile and integrates the
// state in closed form; Ramp is the time-optimal jerk-limited change from (v0, a0) to
// (v_target, 0) of 002_* 2.1 (jerk build-up, [constant acceleration], jerk reduction).
//
// Frames: the planners work in a "frame" with sign s in {+1, -1}: frame quantities are the
// world quantities times s, so in the frame the motion goes forward and A+ limits speeding up
// (positive frame acceleration while the frame velocity is >= 0), A- slowing down.

#include <array>

#include "axes/profile.hpp"
#include "axes/profile_classify.hpp"
#include "jerk/jerk.hpp"

namespace ncsim::axes::detail {

// The velocity change, its distance and the rest-to-speed ramp distance are the jerk kernel's
// (jerk/jerk.hpp): one home for the 1-D maths shared with planner, ipo and conveyor.
using jerk::distance;
using jerk::Ramp;
using jerk::ramp_distance;
using jerk::velocity_ramp;

/// Appends phases to a Profile; state integration in closed form.
class ProfileBuilder {
 public:
  ProfileBuilder(Profile& out, const MotionState& start) noexcept;

  /// Appends a phase with world jerk `jerk` lasting `duration`; durations <= 0 are skipped.
  void add(double jerk, double duration) noexcept;
  /// As add(jerk, duration), then sets the acceleration to its intended end value `a_end`.
  void add(double jerk, double duration, double a_end) noexcept;
  /// Appends the phases of `change` in the frame with sign `sign`; the state after each phase
  /// is set to its intended value (acceleration +-a_peak, then velocity v_end with a = 0).
  void add(const Ramp& change, double sign) noexcept;
  /// Appends the phases of `cross` in the frame with sign `sign`; the state after each phase is
  /// set to its intended value (acceleration +-a_peak, then v = 0 with +-a_zero).
  void add(const jerk::Crossing& cross, double sign) noexcept;
  /// Appends the phases of `tail`, a profile planned from the builder's current state (same
  /// values), unchanged but for their start times; the state becomes tail's end state.
  void add(const Profile& tail) noexcept;
  /// Marks the current time as the start of the braking phase.
  void mark_brake() noexcept { out_.t_brake_ = t_; }
  void set_level(double v_level) noexcept { out_.v_level_ = v_level; }

  const MotionState& state() const noexcept { return state_; }
  double time() const noexcept { return t_; }

  /// Completes the profile; `exact_end` (when given) replaces the integrated end state, so the
  /// target is met exactly after the last phase. The end acceleration is zero.
  void finish(const MotionState* exact_end = nullptr) noexcept;

 private:
  /// Appends the phases of a jerk pulse (a Ramp's or a Crossing's, frame sign `sign`): phase i
  /// where duration[i] > 0, the acceleration then set to a_end[i] (world) and, after the last,
  /// the velocity to v_end (world).
  void add_pulse(const std::array<double, 3>& jerk, const std::array<double, 3>& duration,
                 double sign, const std::array<double, 3>& a_end, double v_end) noexcept;

  Profile& out_;
  MotionState state_;
  double t_ = 0.0;
};

/// Frame clamp: brings a frame acceleration beyond [-a_down, a_up] back to the limit with
/// jerk (decision "limits first", docs/axes-profile.md). Appends to `builder` in world frame.
void clamp_acceleration(ProfileBuilder& builder, double sign, const Dynamics& dynamics) noexcept;

/// Appends a rest-to-rest move from the builder's (resting) state to `p_target` under the
/// manual's rule for an unreachable V (002_* 2.1, symmetric min(A+, A-)).
void append_rest_to_rest(ProfileBuilder& builder, double p_target,
                         const Dynamics& dynamics) noexcept;

/// Appends a stop to rest from the builder's state (frame = direction of motion).
void append_stop(ProfileBuilder& builder, const Dynamics& dynamics) noexcept;

/// Appends the phases of a kernel move (frame sign move.sign).
void append_move(ProfileBuilder& builder, const jerk::Move& move) noexcept;

/// ProfileRule::time_optimal: plans jerk::fastest_move (or stop, then the fastest move) into
/// `out` (exact end); false when neither reaches the target. `direct`: the move goes toward
/// the target from a start not moving away, so the manual plan need not be compared.
/// Inputs as checked by plan_position (valid limits, finite values, |target.v| <= V).
/// `stop`: the start's stop point where plan_fastest computed it (its candidate 4's bound),
/// else left as it was (t < 0 marks it unknown).
bool plan_fastest(const MotionState& start, const PositionTarget& target, const Dynamics& dyn,
                  Profile& out, bool& direct, StopPoint& stop) noexcept;

/// Sign of the direction of motion of `state`: of v, else of a, else `fallback`.
double motion_sign(const MotionState& state, double fallback) noexcept;

}  // namespace ncsim::axes::detail

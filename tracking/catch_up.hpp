#pragma once
// tracking/catch_up: the synchronisation movement after #SYNC IN (seed 004 §2.1.1, §2.1.1.1).
//
// Purpose: plan the PTP motion of every axis from its current, possibly moving, command state
// to a target point fixed in PCS1, i.e. moving with the belt in MCS, meeting it with the
// relative velocity FEED_CONT (0: moving with the belt) and acceleration 0 (004 l.284-286).
// Inputs: per axis the start state (MCS command position, velocity, acceleration), where the
// target is at the start of the catch-up (MCS), the component of the belt velocity on the
// axis (direction() x belt velocity, SyncFrame), the tool's velocity relative to the target
// at the meeting, the axis's PTP dynamics; the belt travel s0 at the start.
// Outputs: one axes::Profile per axis, all started together; the common meeting time; the
// setpoint at time t for the belt travel s(t) actually reached.
// Method (docs/conveyor.md "Synchronisation"): per axis the earliest meeting alone:
// axes::plan_moving_target for a meeting at the target's velocity (FEED_CONT 0), the same
// search on plan_position for a meeting at another velocity; where the PTP core's single-peak
// family has no such profile (a moving axis ahead of a faster target needs a velocity dip
// below its start and end velocity), a position move in the frame moving with the target
// under V - |w| (stop and return included); the slowest sets the meeting
// time T; every other axis gets axes::plan_position_of_duration to (p1 + w T, w + r) in
// exactly T, so all axes start together and arrive together. Where the single-peak family
// cannot be stretched to T (a start moving the wrong way), an axis meeting at the target's
// velocity keeps its own earlier meeting and then moves with the target (the manual's "in
// general the axes do not reach the target point at the same time", 004 l.266); an axis
// meeting at another velocity cannot, and the plan fails (kCatchUpNotSynchronizableId).
// The belt forecast is constant velocity (the belt's at the start); setpoint() adds the belt's
// deviation from it, s(t) - s0 - v t, along each axis's conveying component, so a belt
// changing velocity during the catch-up still ends exactly on the moving target (its
// acceleration goes into the axes, as while machining in PCS1).
// Invariants: plan() never throws and never allocates; after a successful plan, setpoint(i, t,
// s, ...) for t >= meeting(i) is the target point at travel s plus r (t - meeting(i)).

#include <array>
#include <cstddef>
#include <span>

#include "axes/profile.hpp"
#include "planner/move.hpp"

namespace ncsim::tracking {

/// NC9050: no catch-up motion of the required kind exists (the axis named in the message).
inline constexpr const char* kCatchUpNotSynchronizableId = "NC9050";

/// One axis of the catch-up.
struct CatchUpAxis {
  axes::MotionState start;  ///< command state at the start [mm, mm/s, mm/s^2] (MCS)
  double target = 0.0;      ///< where the target is at the start, belt travel s0 [mm] (MCS)
  double conveying = 0.0;   ///< component of the conveying direction on this axis [-]
  double v_relative = 0.0;  ///< tool velocity relative to the target at the meeting [mm/s]
  axes::Dynamics dynamics;  ///< PTP dynamics of the axis (V, A+, A-, J)
};

class CatchUp {
 public:
  static constexpr std::size_t kMaxAxes = planner::kMaxAxes;

  /// Plans the catch-up of `axes` (at most kMaxAxes) against a belt at travel `s0` [mm] moving
  /// with `v_belt` [mm/s] along PCS0 X. On a non-ok result `failed_axis()` names the axis.
  axes::Result plan(std::span<const CatchUpAxis> axes, double s0, double v_belt) noexcept;

  /// Command of axis i at t [s] since the start, for the belt's travel `s` [mm], velocity `v`
  /// [mm/s] and acceleration `a` [mm/s^2] along PCS0 X reached then.
  axes::Setpoint setpoint(std::size_t i, double t, double s, double v, double a) const noexcept;
  /// Where the target of axis i is at travel `s` [mm] (MCS).
  double target_at(std::size_t i, double s) const noexcept;

  double duration() const noexcept { return duration_; }  ///< common meeting time T [s]
  /// The forecast belt velocity along PCS0 X the plan assumed [mm/s].
  double belt_velocity() const noexcept { return v_belt_; }
  /// The meeting time of axis i [s]: duration(), or earlier where the axis could not be
  /// stretched (then it moves with the target from there).
  double meeting(std::size_t i) const noexcept { return meet_[i]; }
  std::size_t axis_count() const noexcept { return n_; }
  int failed_axis() const noexcept { return failed_; }  ///< -1: none
  const axes::Profile& profile(std::size_t i) const noexcept { return profiles_[i]; }

 private:
  std::array<axes::Profile, kMaxAxes> profiles_{};
  std::array<CatchUpAxis, kMaxAxes> axes_{};
  std::array<double, kMaxAxes> meet_{};
  std::array<bool, kMaxAxes> belt_frame_{};  ///< profile i is relative to its moving target
  std::size_t n_ = 0;
  double duration_ = 0.0;
  double s0_ = 0.0;
  double v_belt_ = 0.0;
  int failed_ = -1;
};

/// The earliest meeting of one axis alone with a target at p1 + w t, at velocity w + r and
/// acceleration 0 (r = 0: axes::plan_moving_target). `t_meet` [s] receives its time.
axes::Result plan_meeting(const axes::MotionState& start, double p1, double w, double r,
                          const axes::Dynamics& dynamics, axes::Profile& out,
                          double& t_meet) noexcept;

}  // namespace ncsim::tracking

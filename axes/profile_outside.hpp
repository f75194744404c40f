#pragma once
// axes/profile_outside: ProfileRule::time_optimal from a start outside the limits (issue 11:
// "brought back inside as fast as possible"; docs/axes-profile-outside.md).
//
// Purpose: a start with |v| > V, an acceleration beyond A+ (speeding up) or A- (slowing down),
// or an acceleration whose release at full jerk forces |v| beyond V, is first brought inside
// by the recovery (the excess removed at full jerk, docs/axes-profile-outside.md), and
// the time-optimal profile follows from the first state inside. The manual (default) rule has
// its own, smaller recovery for the starts whose forced part reverses the motion
// (manual_recover), then the manual plan.
// Inputs: a MotionState, Dynamics (V, A+, A-, J), a PositionTarget.
// Outputs: the Recovery (its constant-jerk phases and the first state inside); the whole
// profile (recovery, then the time-optimal continuation), ending exactly on the target.
// Invariants: the recovery is empty for a start inside; while outside, |a| never grows beyond
// max(|a0|, the limit it is taken to) and the velocity never moves beyond what the start
// forces; from the first state inside on, the profile is the time-optimal planner's.

#include <array>
#include <cstddef>

#include "axes/profile.hpp"

namespace ncsim::axes::detail {

/// True when `s` lies outside the limits: |v| > V, |a| beyond A+ (speeding up, or at rest)
/// or A- (slowing down), the release of a at full jerk ending beyond +-V, or crossing v = 0
/// with |a| beyond A+ (relative tolerance kRelRounding, so a start on a limit is inside).
bool outside_limits(const MotionState& s, const Dynamics& dyn) noexcept;

/// The recovery from a start outside the limits: up to kMaxPhases constant-jerk phases.
struct Recovery {
  static constexpr std::size_t kMaxPhases = 8;
  std::array<double, kMaxPhases> jerk{};      ///< world jerk of each phase [mm/s^3]
  std::array<double, kMaxPhases> duration{};  ///< [s]
  std::array<double, kMaxPhases> a_end{};     ///< acceleration at each phase's end, exact [mm/s^2]
  std::size_t count = 0;                      ///< phases used
  MotionState end;                            ///< first state inside the limits
  /// Total duration of the recovery [s].
  double time() const noexcept;
};

/// The recovery from `start` (empty when the start is inside); false when the phases did not
/// suffice (never seen; the caller then plans without it).
bool recover(const MotionState& start, const Dynamics& dyn, Recovery& out) noexcept;

/// The time-optimal profile from a start outside the limits: the recovery, then
/// plan_position(..., time_optimal) from its end state. False (out untouched) when the
/// recovery fails or both together need more than Profile::kMaxPhases phases.
bool plan_from_outside(const MotionState& start, const PositionTarget& target, const Dynamics& dyn,
                       Profile& out) noexcept;

/// The manual rule's recovery (docs/axes-profile-outside.md, "The manual rule"): only the
/// excesses whose forced part reverses the motion, which the manual chain (planned in the frame
/// of the target) would otherwise ride or brake with A+ instead of A-: a release ending beyond
/// -V (the release, then the manual's velocity change to the level V with A-, a = 0 on arrival,
/// 002_* 2.2), and a braking beyond A- that reaches v = 0 before -A- (the clamp's jerk up to
/// v = 0). Empty for any other start (the manual plan's "limits first" handles those itself).
bool manual_recover(const MotionState& start, const Dynamics& dyn, Recovery& out) noexcept;

/// ProfileRule::manual from a start that manual_recover brings inside: the recovery, then
/// plan_position(..., manual) from its end state. False (out untouched) when the recovery is
/// empty or both together need more than Profile::kMaxPhases phases.
bool plan_manual_from_outside(const MotionState& start, const PositionTarget& target,
                              const Dynamics& dyn, Profile& out) noexcept;

}  // namespace ncsim::axes::detail

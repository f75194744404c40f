#pragma once
// axes/profile_classify: cheap closed-form lower bounds on the duration of the time-optimal
// rule's slower candidates, so plan_fastest / plan_position decide before solving that a
// candidate cannot win and skip it (issue 11, "Speed"; docs/axes-profile.md).
//
// Inputs: the start state, the target, the dynamics (as plan_position).
// Outputs: durations [s]; a lower bound is <= the candidate's planned duration (with a margin
// of kRelTol relative for rounding), 0 where no bound is known (the candidate is then evaluated).
// Invariants: skipping a candidate whose bound is >= the best duration found changes nothing
// (plan_fastest keeps a candidate only when it is strictly faster); checked against the full
// search by profile_classify_test.cpp. Nothing allocates, nothing throws.

#include <cmath>
#include <limits>

#include "axes/profile.hpp"

namespace ncsim::axes::detail {

/// The stop of plan_fastest's candidate 4 and of the manual's stop-and-return (append_stop):
/// its duration [s] and the world position at rest [mm] (to rounding).
struct StopPoint {
  double t = 0.0;  ///< duration of the stop [s]
  double p = 0.0;  ///< position at rest [mm]
};

/// The stop append_stop plans from `start` (acceleration clamp, then the ramp to v = 0).
StopPoint stop_point(const MotionState& start, const Dynamics& dyn) noexcept;

/// Duration [s] of the S-ramp between rest and v >= 0 [mm/s] under a_lim, j (both ends at
/// a = 0; jerk::ramp_distance's ramp): 2 sqrt(v / j) without a hold, v / a_lim + a_lim / j with
/// one; its phases' sum to rounding (1e-15), without building them.
inline double rest_ramp_time(double v, double a_lim, double j) noexcept {
  return v * j <= a_lim * a_lim ? 2.0 * std::sqrt(v / j) : v / a_lim + a_lim / j;
}

/// Duration [s] of the fastest rest-to-rest move over `dist` >= 0 [mm] under the real A+, A-
/// (the closed form of profile_optimal.cpp).
double rest_to_rest_fastest_time(double dist, const Dynamics& dyn) noexcept;

/// Lower bound [s] of "stop, then the fastest move from rest to the target" (plan_fastest's
/// candidate 4: for an arrival velocity the single-peak move from rest, jerk::fastest_move);
/// infinite where that move cannot exist (the target behind or closer than the ramp to the
/// arrival speed).
/// `stop_out` (when given) receives the stop point (for manual_bound).
double stop_then_go_bound(const MotionState& start, const PositionTarget& target,
                          const Dynamics& dyn, StopPoint* stop_out = nullptr) noexcept;

/// Lower bound [s] of the manual plan (ProfileRule::manual) where it stops and returns
/// (a start moving away from the arrival direction, or one that never moves backward with the
/// target behind it); 0 otherwise. `known`: the start's stop point where already computed.
double manual_bound(const MotionState& start, const PositionTarget& target, const Dynamics& dyn,
                    const StopPoint* known = nullptr) noexcept;

/// Lower bound [s] of the two-peak change (plan_fastest's candidate 2, jerk::two_peak_move):
/// max(D / max(|v0|, |v1|), the time-optimal velocity change v0 -> v1 under max(A+, A-));
/// 0 where it has no bound (no distance, a start acceleration beyond both limits). The
/// velocity change is left out where the first term alone is already >= `enough` [s].
double two_peak_bound(const MotionState& start, const PositionTarget& target, const Dynamics& dyn,
                      double enough = std::numeric_limits<double>::infinity()) noexcept;

}  // namespace ncsim::axes::detail

#pragma once
// tracking/sync_checks: the run-time checks and the dynamics split of conveyor tracking (seed 004
// §2.1.2, §3 #SYNC IN; docs/conveyor.md "Synchronisation").
//
// Purpose: the rules the channel applies while synchronised, as pure functions.
// Inputs: velocities [mm/s], the planner's per-axis limits, the conveying component of an axis.
// Outputs: an error (id and message) or nothing; the limits a PCS1 block may use.
// Invariants: pure; never throw.

#include <optional>
#include <string>

#include "core/tolerance.hpp"
#include "planner/move.hpp"

namespace ncsim::tracking {

/// Error 50653 (004 l.514): the conveyor's velocity is more than 10 % above CONV_VEL.
inline constexpr const char* kBeltTooFastId = "50653";
/// Error 50587 (004 l.515): CONV_VEL above the maximum velocity in the conveying direction.
inline constexpr const char* kConvVelTooHighId = "50587";
/// The factor of 004 l.514: "If the actual velocity is 10 % higher than specified".
inline constexpr double kBeltVelocityTolerance = 1.10;
/// The relative rounding a belt velocity measured from position differences
/// may carry above the limit and still pass [1]. (p_k - p_k-1) / T with |p| the belt travel
/// rounds by up to 2.2e-16 |p| / T (an ulp of each position), the filter's weighted sum adds
/// a few ulp of v: 1e-9 of 330 mm/s (0.33 um/s) covers a travel up to 1e-9 v T / 2.2e-16 =
/// 1500 m at 1 ms (75 min of a 330 mm/s belt), far below the 1 mm/s between 330 and 331.
inline constexpr double kBeltVelocityRounding = kRelTol;

struct SyncError {
  std::string id;  ///< the manual's id (50653, 50587, P-ERR-44009 from the Port) or NC90xx
  std::string message;
};

/// 50653 when |v_belt| > 1.10 * conv_vel (strictly: CONV_VEL 300 mm/s allows 330 mm/s; a
/// measured 330 rounding up to kBeltVelocityRounding above it passes, belt-split).
/// ncsim decision: `v_belt` is the master velocity the PCS1 frame follows (Port::master(),
/// filtered, as the NC sees it: the unfiltered value's noise would trip it), checked every
/// cycle from #SYNC IN (its wait for the measured value included) to #SYNC OUT.
std::optional<SyncError> check_belt_velocity(double v_belt, double conv_vel);

/// 50587 when the belt component on an axis, |conveying| * conv_vel, exceeds its v_max: the
/// interpreter checks X at decode (interp/interpreter_hash.cpp); this is the same rule for any
/// axis the conveying direction has a component on (a rotated T0).
std::optional<SyncError> check_conv_vel(const planner::AxisLimits& axis, double conveying,
                                        double conv_vel, const std::string& axis_name);

/// The limits a PCS1 block is planned with on an axis whose conveying component is
/// `conveying` (004 l.311-319): the belt takes |conveying| * v_conv of the axis's velocity,
/// v_max - v_conv is left in the conveying direction and v_max + v_conv against it; the
/// planner has one symmetric limit, so the smaller one, v_max - v_conv, applies both ways
/// (v_reference and v_rapid alike); --- belt-split: a line against the belt gets v_max +
/// CONV_VEL instead (BeltSplit::split, guarded by Channel::sync_belt_cap).
/// v_conv = 1.10 * CONV_VEL: the fastest belt 50653 lets through, so X never exceeds v_max
/// without an error first. Accelerations and jerk are left
/// unchanged: the belt's own acceleration adds to them (docs/conveyor.md). Requires
/// check_conv_vel() passed; a v_max that would drop to 0 or less is kept at 1 % of itself.
planner::AxisLimits pcs1_limits(const planner::AxisLimits& axis, double conveying, double conv_vel);
/// The velocity the belt takes of that axis in pcs1_limits [mm/s]:
/// |conveying| * 1.10 * conv_vel (what ProgramSource puts into planner::Move::belt).
double pcs1_belt(double conveying, double conv_vel) noexcept;

}  // namespace ncsim::tracking

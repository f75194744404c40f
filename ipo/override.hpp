#pragma once
// ipo/override: path override and feed hold inside the path interpolator (issue 13).
//
// Purpose: the maths of a run-time velocity change on the path: which level an override
// factor asks for under each override type (000 §7.5.6 l.351-357, 002 l.346-355), and a
// jerk-limited plan from the path state at the moment of the change (s, v, a; a may be != 0)
// to the end of the active look-ahead entry that keeps every ceiling of the 100 % plan.
// Inputs: the state, the remaining length of the entry, the target level and exit, the
// entry's exit velocity planned at 100 % (joint caps, planned stops) and its path a, d, j.
// Outputs: PathPlan (first ramp from the state, cruise, ramp to the exit), evaluated in
// closed form by plan_at(); make_plan() answers false when no plan fits (the caller keeps
// the plan it follows, which fits by construction).
// Method (docs/ipo.md "Override and feed hold"): the exit is the lowest velocity in
// [wanted, cap] whose ramp from the state fits the length (the distance of a jerk-limited
// slow-down is not monotone in its end velocity, so the search is a grid plus bisection, not
// one bisection); the level is the highest in [exit, target] whose two ramps fit ("iterated":
// 002 l.354-355, an unreachable level gives the highest reachable lower one). A target level
// 0 (override 0, feed hold) ends the plan at v = 0 on the path: the path holds there.
// Invariants: every ramp comes from jerk::velocity_ramp with the entry's a, d, j, so |a| and
// |j| stay within the path limits; v stays in [0, max(v0 + a0^2/2j, level)] and the exit is
// at most the planned one, so every stop and joint cap planned at 100 % holds at any override.

#include <cstdint>
#include <span>

#include "jerk/jerk.hpp"
#include "planner/chain.hpp"
#include "planner/joint_limits.hpp"
#include "planner/lookahead.hpp"
#include "planner/move.hpp"
#include "planner/prepare.hpp"

namespace ncsim::ipo {

/// Path override type: the velocity the factor refers to (000 §7.5.6; ncsim key
/// NCSIM-CHAN-630 `override_type`, docs/machines.md).
enum class OverrideType : std::uint8_t {
  reduced,            ///< "Reduced (iterated)" (default): factor x the level of the 100 % profile
  original,           ///< "Original (iterated)": factor x programmed F, capped by the 100 % level
  reduced_above_100,  ///< "Reduced [0 .. >100 %]": as reduced; above 1 up to the axes' G00
                      ///< velocities and dynamics
};

/// Largest factor each type accepts: 1 (002 l.348: 0 .. 100 %), kMaxOverride for
/// reduced_above_100 (000 l.357 names no limit; ncsim bounds it at 1000 %).
inline constexpr double kMaxOverride = 10.0;
double max_override(OverrideType type) noexcept;

/// Name of a type as written in the machine list ("REDUCED", "ORIGINAL", "REDUCED_ABOVE_100").
const char* override_type_name(OverrideType type) noexcept;

/// The level an override factor asks for on an entry [mm/s].
/// level_100: cruise level of the entry's 100 % profile; v_programmed: its programmed
/// velocity; raised_cap: the cap above 100 % (reduced_above_100 only, else ignored).
double override_level(OverrideType type, double factor, double level_100, double v_programmed,
                      double raised_cap) noexcept;
/// The exit velocity wanted at the end of an entry [mm/s], at most exit_100 (the 100 % plan).
double override_exit(OverrideType type, double factor, double exit_100,
                     double v_programmed) noexcept;

/// Velocity cap and path a, d, j of an entry above 100 % (reduced_above_100): each axis at
/// MIN(G00, reference, maximum velocity) (000 l.357, l.360) and the path limits that keep every
/// axis inside its a and j at that velocity (planner::limits_from_bounds over the entry's
/// derivative bounds); a, d, j are also at most the planned ones (the same ramps).
struct RaisedLimits {
  double v_max = 0.0;  ///< [mm/s]
  double a = 0.0;      ///< [mm/s^2]
  double d = 0.0;      ///< [mm/s^2]
  double j = 0.0;      ///< [mm/s^3]
};
RaisedLimits raised_limits(const planner::PlannedSegment& entry,
                           std::span<const planner::AxisLimits> axes) noexcept;
/// The same under #TRAFO ON (ipo/override_trafo.cpp): the joints' G00 rule
/// MIN(rapid, reference, maximum) per joint along the joints' derivative bounds of the entry
/// (planner::joint_bounds), each joint inside its a and j; a, d, j at most the planned ones.
/// The planned limits when the inverse fails or nothing is gained.
RaisedLimits raised_limits_joints(const planner::PlannedSegment& entry,
                                  const planner::JointLimits& joints) noexcept;

/// A velocity plan on the active entry from the state at s0 to the entry's end (or to a hold).
struct PathPlan {
  planner::SegmentProfile profile;  ///< first ramp from (v0, a0), cruise, second ramp to the exit
  double s0 = 0.0;                  ///< arc length of the start on the entry [mm]
  bool hold = false;                ///< ends at v = 0 after the first ramp and holds there
  double length = 0.0;  ///< arc length the plan covers [mm] (the rest of the entry unless hold)
  /// Duration until the entry end or the hold [s].
  double time() const noexcept { return hold ? profile.t_first : profile.time(); }
  /// Velocity at the end of the plan [mm/s].
  double v_exit() const noexcept;
};

/// Path state at time t [s] after the plan's start (t clamped to [0, time()]); s is the arc
/// length on the entry (s0 + distance).
planner::PathState plan_at(const PathPlan& plan, double t) noexcept;

/// What a new plan must meet.
struct PlanRequest {
  double v0 = 0.0;           ///< path velocity now [mm/s], >= 0
  double a0 = 0.0;           ///< path acceleration now [mm/s^2]
  double length = 0.0;       ///< arc length to the end of the entry [mm]
  double level = 0.0;        ///< target level [mm/s] (0: stop and hold)
  double exit_wanted = 0.0;  ///< exit velocity wanted [mm/s]
  double exit_cap = 0.0;     ///< exit planned at 100 % [mm/s]: never exceeded
  double a = 0.0;            ///< path acceleration limit [mm/s^2]
  double d = 0.0;            ///< path deceleration limit [mm/s^2]
  double j = 0.0;            ///< path jerk limit [mm/s^3]
};

/// Builds the plan (s0 = 0; the caller shifts it). False when no exit in [wanted, cap] can be
/// reached within the length from the state.
bool make_plan(const PlanRequest& request, PathPlan& out) noexcept;

/// Time [s] at which the 100 % profile reaches arc length s (bisection on the monotone s(t);
/// s beyond the profile's length gives its duration).
double profile_time_at(const planner::SegmentProfile& profile, double s) noexcept;

}  // namespace ncsim::ipo

#pragma once
// planner/joint_limits: path limits from the joints of a kinematic transform (#TRAFO ON).
//
// Purpose: under a transform (delta robot, #KIN ID[37]) the path is planned in Cartesian space
// but every joint must keep its own v, a, j. This is an extra limit source: the joints' path
// limits are computed like the axes' (limits_from_bounds) from bounds of the joint derivatives
// with respect to the path's arc length, and the smaller limits win.
// Inputs: a Segment (Cartesian path, machine axes 0..2 = X, Y, Z), its Move, the axis limits,
// a JointMap (inverse transform: Cartesian point -> joint values), the joint limits (one
// planner::AxisLimits per joint, from machines::AxisParams by the adapter).
// Outputs: PathLimits with v, a, d, j no larger than the axis-only limits; limit == joint and
// limiting_axis = the joint when a joint sets the velocity cap.
// Method (docs/planner.md "Kinematics"): joint q(s) = IK(x(s)). At each sample s_k the path is
// replaced by its third-order Taylor polynomial x + h x' + h^2/2 x'' + h^3/6 x''' (exact to
// third order, so q', q'', q''' at s_k are those of the true path); IK at h = 0, +-d, +-2d gives
// q', q'', q''' by central differences (d = kJointStep). Samples are spaced ds <= kJointSpacing
// (at least kJointMinSamples, at most kJointMaxSamples per segment). Between samples:
//   |q'|   <= max_k |q'_k| + ds/2 * D2,   |q''| <= max_k |q''_k| + ds/2 * D3,
//   |q'''| <= max_k |q'''_k| * (1 + kJointMargin)
// (a mean-value bound for the first two; the documented margin for the third, checked by the
// delta test against joint jerks from a finely sampled plan). Any motion inside the returned
// limits then keeps every joint inside its v, a, j by the same projection as the axes.
// Invariants: returns nullopt (the segment cannot be planned) when IK fails at a sample:
// the caller reports the kinematic error (NC3201 workspace, NC3202 joint limit).

#include <cstdint>
#include <functional>
#include <optional>
#include <span>

#include "planner/limits.hpp"

namespace ncsim::planner {

/// Inverse transform: Cartesian point (AxisVec, axes 0..2) -> joint values (AxisVec, joints
/// 0..joint_count-1); false when the point is not reachable.
using JointMap = std::function<bool(const AxisVec& cartesian, AxisVec& joints)>;

inline constexpr double kJointStep = 0.05;     ///< finite-difference step d along s [mm]
inline constexpr double kJointSpacing = 1.0;   ///< largest sample spacing ds [mm]
inline constexpr int kJointMinSamples = 16;    ///< samples per segment, at least
inline constexpr int kJointMaxSamples = 2048;  ///< samples per segment, at most
inline constexpr double kJointMargin = 0.05;   ///< relative margin on sampled |q'''|

/// Bounds of |dq_i/ds|, |d2q_i/ds2|, |d3q_i/ds3| over the segment, or nullopt if IK fails.
std::optional<DerivativeBounds> joint_bounds(const Segment& segment, const JointMap& inverse,
                                             std::size_t joint_count);

/// dq/ds and d2q/ds2 of the joints at one path point (the same Taylor polynomial and central
/// differences as joint_bounds); false when IK fails there. Used at corners: the joint
/// velocity step at a C0 joint is v (q'_out - q'_in), the acceleration step at C1
/// v^2 (q''_out - q''_in) (docs/planner.md "Kinematics").
bool joint_derivatives(const PathPoint& point, std::size_t axis_count, const JointMap& inverse,
                       std::size_t joint_count, AxisVec& d1, AxisVec& d2);

/// The limits a joint runs a G00 with under a transform: the G00 slope (rapid_limits) and the
/// velocity MIN(rapid, reference, maximum) (000 l.360). Used by path_limits and by the adapter's
/// belt share of a G00 in PCS1 (program/trafo_path.cpp), which must see the same limits.
AxisLimits joint_rapid_limits(const AxisLimits& joint) noexcept;

/// Path limits of `segment` under the axis limits AND the joint limits (the smaller of each).
/// nullopt when IK fails somewhere on the segment.
std::optional<PathLimits> path_limits(const Segment& segment, const Move& move,
                                      std::span<const AxisLimits> axes, const JointMap& inverse,
                                      std::span<const AxisLimits> joints);

}  // namespace ncsim::planner

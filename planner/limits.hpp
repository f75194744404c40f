#pragma once
// planner/limits: path limits of one segment from the limits of its axes.
//
// Purpose: turn per-axis v, a, j (and the programmed feed) into the path quantities the
// look-ahead plans with: a velocity cap V, path acceleration / deceleration A+ / A- and path
// jerk J, such that ANY path motion on the segment with 0 <= v <= V, |a| <= A and |j| <= J
// keeps every axis inside its own limits.
// Inputs: a Segment (its derivative bounds), the Move it came from (feed, rapid, G93, E,
// slope), the axis limits.
// Outputs: PathLimits, including which limit set V and whether the programmed F was capped.
// Method (docs/planner.md "Path limits"): with x_i(s(t)) the axis chain rule gives
//   v_i = x'_i v,   a_i = x''_i v^2 + x'_i a,   j_i = x'''_i v^3 + 3 x''_i v a + x'_i j,
// so with the bounds |x'_i| <= D1, |x''_i| <= D2, |x'''_i| <= D3 of the segment:
//   V <= v_i,max / D1                      (axis velocity; G00: MIN(rapid, ref, max), 000 l.360)
//   V <= sqrt(0.75 a_i / D2)               (centripetal acceleration takes at most 3/4)
//   A  = (a_i - D2 V^2) / D1               (the rest is left for the path acceleration)
//   V <= cbrt(0.5 j_i / D3), A <= 0.25 j_i / (3 D2 V)  (jerk-limited slopes only)
//   J  = (j_i - D3 V^3 - 3 D2 V A) / D1
// minimised over the axes. On lines D2 = D3 = 0 and the limits are the plain projections.
// Invariants: every output finite and > 0 for a segment of positive length; V <= the
// programmed velocity.

#include <array>
#include <cstdint>
#include <span>

#include "planner/move.hpp"
#include "planner/path.hpp"

namespace ncsim::planner {

/// Which limit set a segment's velocity cap.
enum class VelocityLimit : std::uint8_t {
  programmed,      ///< the programmed F (or G93 time, or the rapid rule) is reachable
  axis_velocity,   ///< an axis maximum / reference velocity caps F (noted in time --blocks)
  centripetal,     ///< an axis acceleration on the curvature
  curvature_jerk,  ///< an axis jerk on the change of curvature
  joint,           ///< a joint of the kinematic transform (v, a or j; joint_limits.hpp)
};

/// Path limits of one segment.
struct PathLimits {
  double v_programmed = 0.0;  ///< what the block asks: F, L / G93 time, or the G00 velocity [mm/s]
  double v_max = 0.0;         ///< velocity cap V on the segment [mm/s]
  double v_end = 0.0;         ///< cap at the block end (E end feed, else v_max) [mm/s]
  double a_max = 0.0;         ///< path acceleration A+ [mm/s^2]
  double d_max = 0.0;         ///< path deceleration |A-| [mm/s^2]
  double j_max = 0.0;         ///< path jerk J [mm/s^3]; +inf for STEP slopes
  VelocityLimit limit = VelocityLimit::programmed;
  std::uint8_t limiting_axis = 0;  ///< axis that set v_max when limit != programmed
  /// F above what the axes allow: capped, with a note in `time --blocks` (isg-language §7.1).
  bool feed_capped() const noexcept { return limit == VelocityLimit::axis_velocity; }
};

/// Share of an axis's acceleration the centripetal part may use (the rest is tangential).
inline constexpr double kCentripetalShare = 0.75;
/// The other shares an arc may take (best_share).
inline constexpr std::array<double, 7> kCentripetalShares = {0.5, 0.6, 0.7, 0.8, 0.85, 0.9, 0.95};
/// Share of an axis's jerk the change of curvature may use at the velocity cap.
inline constexpr double kCurvatureJerkShare = 0.5;
/// Share of an axis's jerk the cross term 3 x'' v a may use.
inline constexpr double kCrossJerkShare = 0.25;

/// How many other limit sets an arc carries (arc_options).
inline constexpr std::size_t kArcOptions = 5;

/// True for the jerk-limited slopes TRAPEZ and SIN2 (HSC is planned like TRAPEZ).
bool jerk_limited(SlopeType slope) noexcept;

/// Path limits of `segment` (from `move`) under `axes` (one entry per machine axis in use).
/// Throws std::invalid_argument when `axes` has fewer entries than the segment's axes.
PathLimits path_limits(const Segment& segment, const Move& move, std::span<const AxisLimits> axes);

/// The projection itself: limits of a curve whose per-axis derivative bounds are `b` (one
/// entry of `axes` per axis), at most `v_programmed` [mm/s], with the jerk rules when `jerk`.
/// path_limits() uses it for the machine axes, joint_limits.hpp for the joints of a
/// kinematic transform. v_end = v_max.
PathLimits limits_from_bounds(const DerivativeBounds& b, std::span<const AxisLimits> axes,
                              double v_programmed, bool jerk,
                              double centripetal_share = kCentripetalShare);
/// An arc whose velocity cap the centripetal acceleration sets: the limits of the share in
/// kCentripetalShares (or `standard`, those at kCentripetalShare) whose expected traverse of
/// `length` [mm] is fastest: a short arc gains more from the tangential acceleration, a long
/// one from the velocity (docs/planner.md "Shares").
PathLimits best_share(const DerivativeBounds& b, std::span<const AxisLimits> axes,
                      double v_programmed, bool jerk, double length, const PathLimits& standard);

/// The limits of an arc under kArcOptions other velocity caps, from the highest the axes allow
/// (centripetal share 0.99) down to 0.58 of it: under a lower cap less of each axis's
/// acceleration goes to the curvature and more is left for the path. `planned` keeps what was
/// programmed (v_programmed, the limit's reason, v_end). Returns how many were filled.
std::size_t arc_options(const Segment& segment, const Move& move, std::span<const AxisLimits> axes,
                        const PathLimits& planned, std::array<PathLimits, kArcOptions>& out);

}  // namespace ncsim::planner

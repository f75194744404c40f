#pragma once
// planner/corner: segment transitions, their class (C0 / C1 / C2) and link velocity.
//
// Purpose: decide how fast the path may pass the joint of two segments without a stop.
// Inputs: the end state of the incoming segment and the start state of the outgoing one
// (PathPoint: tangent x', curvature vector x''), the axis limits, the interpolation cycle T,
// the segments' velocity caps v_in, v_out, and #TRANSVELMIN.
// Outputs: TransitionClass and the link velocity, with which rule set it.
// Rules (docs/planner.md "Corners"):
//   C0 (tangent jumps), VELOJUMP (000 l.108): per axis |dv_i| = v |x'_out,i - x'_in,i| <=
//     C0_i * min(A+_i, |A-_i|) * T; v_link is the largest v meeting every axis, at most
//     min(v_in, v_out); #TRANSVELMIN v_min has priority (000 l.108: "if v_link < v_min then
//     v_link = v_min"), itself at most min(v_in, v_out). A reversal gets what the formula allows
//     (half the step of a 90 degree corner, since |dx'_i| = 2). Path acceleration is 0 there,
//     except at a knee that limits nothing (v_link = min(v_in, v_out)) and whose acceleration
//     step at any path acceleration fits half the C1 budget (knee_carries_acceleration: the
//     0.1 mm chords of CAM output), which carries it.
//   C1 (tangent continuous, curvature jumps), P-CHAN-00009 semantics: the acceleration step
//     v^2 |x''_out,i - x''_in,i| of every axis stays within its jerk budget j_i * T (one cycle
//     at the axis jerk limit), for jerk-limited slopes when ChannelLimits::limit_c1_by_jerk.
//     Path acceleration is 0 there.
//   C2 (curvature continuous): no reduction beyond the segments' caps; the acceleration is
//     carried through.
// Invariants: 0 <= v_link <= min(v_in, v_out).

#include <cstdint>
#include <optional>
#include <span>

#include "planner/move.hpp"
#include "planner/path.hpp"

namespace ncsim::planner {

enum class TransitionClass : std::uint8_t {
  c0,  ///< knee: the tangent jumps (000 l.105)
  c1,  ///< tangent continuous, the curvature (acceleration) jumps
  c2,  ///< curvature continuous
};

/// Tangent directions closer than this are one tangent [rad].
inline constexpr double kTangentTolerance = 1e-6;
/// Curvature vectors closer than this (relative to the larger, or 1e-9 /mm absolute) are equal.
inline constexpr double kCurvatureTolerance = 1e-6;
/// Curvature vectors closer than this count as equal whatever their size [1/mm].
inline constexpr double kCurvatureFloor = 1e-9;

/// Which rule set the link velocity.
enum class LinkRule : std::uint8_t {
  segment_caps,  ///< min(v_in, v_out)
  velojump,      ///< the VELOJUMP axis step (C0)
  transvelmin,   ///< #TRANSVELMIN raised it (C0)
  c1_jerk,       ///< the C1 acceleration-step budget
};

struct Link {
  TransitionClass cls = TransitionClass::c2;
  double v_link = 0.0;             ///< largest velocity at the joint [mm/s]
  bool zero_acceleration = false;  ///< path acceleration 0 at the joint (C0, C1)
  LinkRule rule = LinkRule::segment_caps;
  std::uint8_t limiting_axis = 0;  ///< axis of the VELOJUMP / C1 bound
  double angle = 0.0;              ///< angle between the tangents [rad]
};

/// Angle between two tangents over the metric axes [rad], 0..pi.
double tangent_angle(const AxisVec& t_in, const AxisVec& t_out, std::size_t axis_count,
                     AxisMask metric) noexcept;

/// Class of the joint of `in_end` (end of the incoming segment) and `out_start`.
TransitionClass classify(const PathPoint& in_end, const PathPoint& out_start,
                         std::size_t axis_count, AxisMask metric) noexcept;
/// classify() with the tangent angle of the two points known: `angle` must be
/// tangent_angle(in_end.d1, out_start.d1, axis_count, metric) (for a caller that needs both).
TransitionClass classify_at_angle(const PathPoint& in_end, const PathPoint& out_start,
                                  std::size_t axis_count, double angle) noexcept;

/// VELOJUMP bound alone: the largest v with v |dt_i| <= C0_i min(A+_i, A-_i) T for all i
/// (+inf when no axis changes direction); `axis` receives the limiting axis.
double velojump_velocity(const AxisVec& t_in, const AxisVec& t_out,
                         std::span<const AxisLimits> axes, double t_cycle,
                         std::uint8_t* axis = nullptr) noexcept;

/// Share of the axis jerk budget j_i T that the acceleration step of a knee carrying the path
/// acceleration may take (the rest stays for the curvature steps of curved neighbours).
inline constexpr double kKneeBudget = 0.5;

/// Whether a C0 knee may carry the path acceleration (docs/planner.md "Corners", decision for
/// dense CAM chords): for every axis the acceleration step |a| |t_out,i - t_in,i| at the
/// largest path acceleration the axes allow (|a| <= max_i max(A+_i, A-_i) / max_k |t_k|: the
/// axis with the largest tangent component takes that share of a) stays within
/// kKneeBudget * j_i * T.
bool knee_carries_acceleration(const AxisVec& t_in, const AxisVec& t_out,
                               std::span<const AxisLimits> axes, double t_cycle) noexcept;

/// C1 bound alone: the largest v with v^2 |dk_i| <= j_i T for all i (+inf if none).
double c1_velocity(const AxisVec& k_in, const AxisVec& k_out, std::span<const AxisLimits> axes,
                   double t_cycle, std::uint8_t* axis = nullptr) noexcept;

/// The link at a non-stopping joint. `jerk_limited_slope` selects the C1 rule.
Link link_velocity(const PathPoint& in_end, const PathPoint& out_start, std::size_t axis_count,
                   AxisMask metric, std::span<const AxisLimits> axes, const ChannelLimits& channel,
                   double v_in, double v_out, std::optional<double> transvelmin,
                   bool jerk_limited_slope) noexcept;

}  // namespace ncsim::planner

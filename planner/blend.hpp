#pragma once
// planner/blend: tolerance balls (G61 / G261 with #CONTOUR MODE DEV PATH_DEV = r).
//
// Purpose: replace a non-stopping corner by a smooth curve that stays inside a ball around the
// programmed corner point, so the path keeps its velocity through the corner.
// Inputs: the incoming segment (ending at the corner), the outgoing one (starting there), the
// ball radius r, and how much arc length the ball may take from each (half of each
// neighbouring block, so two balls never overlap; isg-language.md §2.4 "at most half a block").
// Outputs: a Blend: the curve and the arc lengths cut from the two neighbours.
// The curve (docs/planner.md "Blend curve"): a quintic Bezier P0..P5 from the point where the
// incoming segment leaves the ball to the point where the outgoing one leaves it, with
// G2 contact at both ends: B'(0) = lambda x'_in, B''(0) = lambda^2 x''_in, mirrored at the end,
// so position, tangent and curvature are continuous (C2 transitions to both neighbours).
// lambda = 2.5 k(angle) r with k from a table minimising the peak curvature of the line-line
// case. Containment: a Bezier curve lies in the convex hull of its control points, and a ball
// is convex, so checking the six control points against the ball proves the whole curve is
// within r of the corner. If a point is outside (curved neighbours), lambda shrinks, then the
// radius does.
// Radius shrinking: r_eff = min(r, distance from the corner to the half-block points of both
// neighbours), then halved up to 20 times if the control points do not fit.
// Invariants: every point of the curve is at most r_eff <= r from the corner (metric axes);
// its ends are on the ball (distance r_eff) and coincide with the trimmed neighbours' ends;
// cut_in <= max_cut_in, cut_out <= max_cut_out.

#include <optional>

#include "planner/path.hpp"

namespace ncsim::planner {

/// Largest corner angle that is blended [rad] (175 degrees); sharper turns stay C0 corners.
inline constexpr double kMaxBlendAngle = 175.0 * 3.14159265358979323846 / 180.0;

struct Blend {
  Segment curve;         ///< the blend, from the incoming cut point to the outgoing one
  double cut_in = 0.0;   ///< arc length removed from the end of the incoming segment [mm]
  double cut_out = 0.0;  ///< arc length removed from the start of the outgoing segment [mm]
  double radius = 0.0;   ///< ball radius actually used, r_eff <= r [mm]
};

/// The two points of a joint and the angle of their tangents: what the blend and the knee rule
/// (prepare.cpp) both start from, evaluated once.
struct JointEnds {
  PathPoint in_end;     ///< the incoming segment at its end
  PathPoint out_start;  ///< the outgoing segment at its start
  double angle = 0.0;   ///< tangent_angle of their tangents over the metric axes [rad]
};

/// The ends of the joint between `in` and `out` (axes and metric of both).
JointEnds joint_ends(const Segment& in, const Segment& out);

/// The blend of the corner between `in` and `out`, or nullopt when the corner is not blended
/// (angle below the tangent tolerance or above kMaxBlendAngle, or no room).
std::optional<Blend> make_blend(const Segment& in, const Segment& out, double radius,
                                double max_cut_in, double max_cut_out);
/// The same with the joint's ends known: `ends` must be joint_ends(in, out).
std::optional<Blend> make_blend(const Segment& in, const Segment& out, const JointEnds& ends,
                                double radius, double max_cut_in, double max_cut_out);

/// Shape factor k(angle) of the blend's end tangents (lambda = 2.5 k r) for a corner angle
/// in radians; 0.71 for a straight line down to 0.08 at 175 degrees.
double blend_shape(double angle) noexcept;

}  // namespace ncsim::planner

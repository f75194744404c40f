#pragma once
// planner/blend: contoured corners: tolerance balls (G61 / G261 with #CONTOUR MODE DEV
// PATH_DEV = r) and corner distances (#CONTOUR MODE DIST PRE_DIST = d_in, POST_DIST = d_out).
//
// Purpose: replace a non-stopping corner by a smooth curve that stays inside a ball around the
// programmed corner point, so the path keeps its velocity through the corner.
// Inputs: the incoming segment (ending at the corner), the outgoing one (starting there), the
// corner distances d_in, d_out (DEV: both r), and how much arc length the blend may take from
// each (half of each neighbouring block, so two blends never overlap; isg-language.md §2.4
// "at most half a block").
// Outputs: a Blend: the curve and the arc lengths cut from the two neighbours.
// The curve (docs/planner.md "Blend curve"): a quintic Bezier P0..P5 from the point of the
// incoming segment at distance d_in from the corner to the point of the outgoing one at d_out,
// with G2 contact at both ends: B'(0) = lambda_in x'_in, B''(0) = lambda_in^2 x''_in, mirrored
// at the end with lambda_out, so position, tangent and curvature are continuous (C2
// transitions to both neighbours). lambda = 2.5 k(angle) d per end, with k from a table
// minimising the peak curvature of the symmetric line-line case. Containment: a Bezier curve
// lies in the convex hull of its control points, and a ball is convex, so checking the six
// control points against the ball of radius max(d_in, d_out) proves the whole curve is within
// it. If a point is outside (curved neighbours), both lambdas shrink, then both distances.
// Distance shrinking: DEV (one ball): r_eff = min(r, distance from the corner to the
// half-block points of both neighbours); DIST: each end's distance capped by the half-block
// point of its own neighbour (docs/planner.md "DIST"); then both halved up to 20 times if the
// control points do not fit.
// Invariants: every point of the curve is at most radius = max(d_in_eff, d_out_eff) from the
// corner (metric axes), d_in_eff <= d_in, d_out_eff <= d_out; its ends are at d_in_eff and
// d_out_eff from the corner and coincide with the trimmed neighbours' ends;
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
  /// radius of the ball around the corner the curve stays in: max(d_in_eff, d_out_eff), the
  /// ball radius r_eff <= r under DEV [mm]
  double radius = 0.0;
};

/// Where a blend leaves its neighbours: the distance of its ends from the programmed corner
/// over the metric axes.
struct CornerDistances {
  double in = 0.0;   ///< on the incoming segment (DIST PRE_DIST; DEV PATH_DEV) [mm]
  double out = 0.0;  ///< on the outgoing segment (DIST POST_DIST; DEV PATH_DEV) [mm]
  /// true: one ball (DEV), a short neighbour shrinks both ends ("corner distances are
  /// symmetric", isg-language.md §5.3); false (DIST): each end is capped by its own neighbour.
  bool symmetric = true;
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
/// The general form: ends at the corner distances `d` (a ball of radius r is {r, r, true}).
std::optional<Blend> make_blend(const Segment& in, const Segment& out, const JointEnds& ends,
                                const CornerDistances& d, double max_cut_in, double max_cut_out);

/// The corner distances the contour at the end of `move` asks for: {path_dev, path_dev, true}
/// under DEV, {pre_dist, post_dist, false} under DIST; nullopt without contouring.
std::optional<CornerDistances> corner_distances(const Move& move) noexcept;

/// The blend the block `in_move` asks for at its end between its path `in` and the next block's
/// `out` (make_blend with corner_distances(in_move)), or nullopt when it asks for none or the
/// corner is not blended. One place for the planner (prepare.cpp) and for what the adapter
/// predicts of the planner's blends (program/trafo_path.cpp, tracking/x_virtual.cpp), so
/// that both build the same curve under DEV and DIST.
std::optional<Blend> corner_blend(const Move& in_move, const Segment& in, const Segment& out,
                                  const JointEnds& ends, double max_cut_in, double max_cut_out);
/// The same with the joint's ends evaluated here.
std::optional<Blend> corner_blend(const Move& in_move, const Segment& in, const Segment& out,
                                  double max_cut_in, double max_cut_out);

/// Shape factor k(angle) of the blend's end tangents (lambda = 2.5 k r) for a corner angle
/// in radians; 0.71 for a straight line down to 0.08 at 175 degrees.
double blend_shape(double angle) noexcept;

}  // namespace ncsim::planner

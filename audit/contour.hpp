#pragma once
// audit/contour: distance of a point from the programmed contour of one block.
//
// Purpose: the audit's independent measure of contour deviation. It works from the programmed
// Move (start, end, arc centre and direction), not from the planner's Segment, so a mistake in
// trimming, chaining or arc-length parametrisation shows up as a deviation.
// Inputs: a Move (line, arc / helix in the plane of Arc (principal or general), or a cubic
// spline piece) and a point (all axes of the Move).
// Output: a distance [mm] over every axis in use: for a line the Euclidean distance from the
// segment; for an arc the radial error in the plane combined with the error of the other axes
// against their linear motion over the swept angle (an upper bound of the distance from a
// helix, exact for a plane arc), never more than the distance from either end point; for a
// spline piece the distance from its cubic Bezier (evaluated here), 129 samples with every
// local minimum refined by a golden-section search.
// Invariants: 0 for a point on the block (up to rounding); pure.

#include "planner/move.hpp"

namespace ncsim::audit {

/// Distance [mm] of `x` from the programmed block `move`.
double contour_distance(const planner::Move& move, const planner::AxisVec& x) noexcept;

}  // namespace ncsim::audit

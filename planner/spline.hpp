#pragma once
// planner/spline: #SPLINE curves (Akima, B-spline) as pieces with arc-length parametrisation.
//
// Purpose: turn the points of a spline section (isg-language.md §5.4: the start point, then the
// points of the G00/G01 blocks between #SPLINE ON and #SPLINE OFF) into curve pieces the planner
// plans like any other segment: never chopped into lines.
// Inputs: the points one by one (a streaming source: a section of 1,000,000 points is never held
// whole), each with its source line and feed; the spline type; the machine axis count and path
// axes (which measure the arc length).
// Outputs: SplinePiece values, each a Segment of kind spline (a cubic, held as its exact quintic
// degree elevation: point, tangent, curvature, x''' and derivative bounds come from the same
// arc-length machinery as tolerance-ball blends) with the line and feed of its source point.
// Method (docs/planner.md "Splines"):
// - Akima: interpolates the points. Piece k runs from point k to point k + 1 as a cubic Hermite
//   curve in the chord-length parameter h_k = |P_(k+1) - P_k|; the tangent at point i is Akima's
//   weighted mean of the chord directions m_(i-1), m_i with weights |m_(i+1) - m_i| and
//   |m_(i-1) - m_(i-2)| (vector norms; the plain mean when both are 0). At the ends the missing
//   directions are extrapolated as Akima did: m_(-1) = 2 m_0 - m_1, m_(-2) = 2 m_(-1) - m_0 and
//   the mirror at the end. C1 at the points (tangent continuous; curvature may jump: C1 joints).
//   A piece needs the points k - 2 .. k + 3: a window of 6 points.
// - B-spline: the points are the control points of a clamped cubic B-spline with uniform inner
//   knots (0,0,0,0,1,2,...,n-3,n-3,n-3,n-3): it starts at the first point along the first leg,
//   ends at the last point along the last leg, lies in the convex hull of its control polygon
//   (PROG-207263627 "the control polygon bounds it") and is C2 everywhere. Span k (control
//   points k .. k + 3) is converted to its Bezier form by blossoming; it needs the control points
//   k .. k + 3 and whether the end is within 3 points: a window of 7 points.
// - A point equal to the previous one (all axes within kSamePoint) is dropped: it carries no path
// and
//   would make the curve's speed vanish.
// Line and feed: an Akima piece carries the line and feed of the point it ends at (the block
// that programmed it). B-spline span k carries those of control point k + 2 (the point its end
// is pulled towards), the last span those of the last point.
// Invariants: memory is the fixed window (no allocation after construction); pieces come out in
// path order; consecutive pieces share their end / start point exactly.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "planner/move.hpp"
#include "planner/path.hpp"

namespace ncsim::planner {

enum class SplineType : std::uint8_t {
  akima,    ///< #SPLINE TYPE AKIMA: through the points (ISG default type)
  bspline,  ///< #SPLINE TYPE BSPLINE: points are control points
};

/// One programmed point of a spline section.
struct SplineVertex {
  AxisVec point{};         ///< [mm | deg]
  std::uint32_t line = 0;  ///< source line of the block that programmed it
  double feed = 0.0;       ///< programmed F at that block [mm/s]
};

/// One piece of the spline curve.
struct SplinePiece {
  Segment curve;                     ///< kind() == SegmentKind::spline
  std::uint32_t line = 0;            ///< source line (see header comment)
  double feed = 0.0;                 ///< programmed F [mm/s]
  std::array<AxisVec, 4> control{};  ///< the cubic's Bezier control points (curve is exact)
};

/// The Move of a spline piece (what a Move stream carries): the modal state (slope, contour,
/// transition, exact stop, path axes) from `modal`; start, end, feed and line from the piece;
/// Move::spline its inner control points, so Segment::from_move() gives the same curve.
Move spline_move(const SplinePiece& piece, const Move& modal);

/// Near-cusps (issue 34 item 12; docs/planner.md "Splines"): where control points fold back,
/// a piece's speed |B'(t)| nearly vanishes and its curvature peaks; a piece's path limits hold
/// for all of it, so the whole piece would run at the near-cusp's velocity. When the speed
/// sampled at 1,025 parameters falls below kCuspSpeed of its largest, the piece is split by de
/// Casteljau into exact sub-cubics (same curve, same line and feed): at both ends of the
/// interval around it below kCuspExtent (a cubic has at most two) and at halving distances
/// towards its speed minimum, so the path slows down only near the near-cusp. Empty: no near-cusp,
/// the piece stays whole. `path_axes` measure the speed.
std::vector<SplinePiece> split_near_cusp(const SplinePiece& piece, AxisMask path_axes);

/// Speed ratio (of a piece's largest) below which split_near_cusp() splits: 0.5 %. Pieces of
/// CAM-like points come down to about 1.4 % (B-spline, steps of 0.1 .. 5 mm); a fold of 0.001 mm
/// to 0.2 % and less. Segment::bezier_bounds searches below 5 % (correct bounds); the split is
/// for speed only.
inline constexpr double kCuspSpeed = 0.005;
/// The parts around a near-cusp reach out to where the speed is back at 10 % of the largest.
inline constexpr double kCuspExtent = 0.1;

/// Builds the pieces of one spline section from its points, streaming.
class SplineBuilder {
 public:
  /// `axis_count` machine axes, `path_axes` measure the length (Move::path_axes).
  SplineBuilder(SplineType type, std::uint8_t axis_count, AxisMask path_axes);

  /// Adds the next point (the first is the start point). Returns the pieces completed by it
  /// (at most one; valid until the next call).
  std::span<const SplinePiece> push(const SplineVertex& vertex);
  /// Ends the section. Returns the remaining pieces (at most 3 Akima, 4 B-spline; valid until
  /// the next call). The builder is then empty and may start a new section.
  std::span<const SplinePiece> finish();

  /// Points accepted in this section (duplicates dropped).
  std::uint64_t points() const noexcept { return count_; }

 private:
  static constexpr std::size_t kWindow = 8;  ///< ring of the last points (>= 7)

  const SplineVertex& vertex(std::uint64_t index) const noexcept { return ring_[index % kWindow]; }
  AxisVec chord(std::int64_t k) const noexcept;  ///< unit chord direction m_k (extrapolated)
  double chord_length(std::uint64_t k) const noexcept;
  AxisVec akima_tangent(std::int64_t i) const noexcept;
  SplinePiece akima_piece(std::uint64_t k) const noexcept;
  SplinePiece bspline_piece(std::uint64_t k) noexcept;  // sets last_end_
  double knot(std::int64_t k) const noexcept;
  void emit(std::uint64_t k);

  SplineType type_;
  std::uint8_t n_;
  AxisMask path_axes_;
  std::array<SplineVertex, kWindow> ring_{};
  std::uint64_t count_ = 0;    ///< points so far
  std::uint64_t emitted_ = 0;  ///< pieces so far
  bool finished_ = false;      ///< the point count is final (inside finish())
  AxisVec last_end_{};         ///< end of the last B-spline span (the next one starts there)
  std::array<SplinePiece, 4> out_{};
  std::size_t out_n_ = 0;
};

}  // namespace ncsim::planner

#pragma once
// planner/path: path geometry parametrised by arc length.
//
// Purpose: every curve the planner plans on (line, arc, helix, quintic blend) answers the same
// questions at an arc length s: the point x(s), the unit tangent x'(s), the curvature vector
// x''(s) and its derivative x'''(s), one value per machine axis, plus bounds of |x'_i|, |x''_i|,
// |x'''_i| over the whole curve (what path limits project axis limits on).
// Inputs: a Move (line / arc / helix) or the six control points of a blend; a metric mask: the
// axes whose motion measures the arc length (the path axes; if they do not move, every axis).
// Outputs: Segment values. Derivatives are with respect to s, so |x'|_metric == 1.
// Invariants: length() > 0 for a non-degenerate curve (a zero-length move has length 0 and a
// zero tangent); at(0) is the start and at(length()) the end (an arc's end is the programmed
// end point up to the radius check of the interpreter); a trimmed segment is the same curve
// restricted to [s0, s1] and re-parametrised from 0. Pure functions; no allocation.

#include <array>
#include <cstdint>
#include <limits>
#include <variant>

#include "planner/move.hpp"

namespace ncsim::planner {

/// Point and arc-length derivatives at one s.
struct PathPoint {
  AxisVec x{};   ///< position [mm | deg]
  AxisVec d1{};  ///< dx/ds, unit tangent in the metric [1]
  AxisVec d2{};  ///< d2x/ds2, curvature vector [1/mm]
  AxisVec d3{};  ///< d3x/ds3 [1/mm^2]
};

/// Largest |derivative| per axis over a whole segment (for path limits).
struct DerivativeBounds {
  AxisVec d1{};  ///< max |dx_i/ds| [1]
  AxisVec d2{};  ///< max |d2x_i/ds2| [1/mm]
  AxisVec d3{};  ///< max |d3x_i/ds3| [1/mm^2]
  /// Largest curvature |x''| over the metric axes [1/mm]; +inf when not known. There x' is a
  /// unit vector orthogonal to x'', so a metric axis's acceleration x'_i a + x''_i v^2 is at
  /// most sqrt(a^2 + (curvature v^2)^2) (docs/planner.md "Path limits").
  double curvature = std::numeric_limits<double>::infinity();
  AxisMask metric = 0;  ///< the axes the curvature bound holds for
  /// A plane circle (an arc without helix rise): x''' = -curvature^2 x' exactly, so the axis
  /// jerk splits into orthogonal parts too (planner/limits.cpp circle_jerk).
  bool circle = false;
};

namespace geom {

/// A straight line.
struct LineGeom {
  AxisVec p0{};   ///< start [mm | deg]
  AxisVec dir{};  ///< (end - start) / length
};
/// An arc or helix: x(s) = o + lin s + r (cos(theta) u + sin(theta) v), theta = theta0 +
/// omega s, with u, v orthonormal (two unit machine axes for G17 / G18 / G19, any plane under a
/// rotated #CS) and lin the helix rise, orthogonal to the plane.
struct ArcGeom {
  AxisVec p0{};         ///< the start point; points are computed from it [mm | deg]
  AxisVec o{};          ///< centre, plus the start of the axes outside the plane [mm | deg]
  AxisVec lin{};        ///< d x_i/ds of the linear (helix) part [1]
  AxisVec u{};          ///< first in-plane unit vector [1]
  AxisVec v{};          ///< second in-plane unit vector [1]
  double radius = 0.0;  ///< [mm]
  double theta0 = 0.0;  ///< start angle [rad]
  double omega = 0.0;   ///< d theta / ds, signed (+ from u towards v) [rad/mm]
};
/// A quintic Bezier curve with its arc-length table.
struct BezierGeom {
  static constexpr int kTable = 32;  ///< arc-length table intervals of a spline piece (most)
  /// Intervals of a tolerance ball's table (docs/planner.md "Blend curve": 16 keep s(t) within
  /// 1e-13 of the length on every blend shape; spline pieces, whose speed can nearly vanish,
  /// keep 32).
  static constexpr int kBlendTable = 16;
  std::array<AxisVec, 6> p{};
  std::array<double, kTable + 1> s_at{};  ///< arc length at t = k / intervals, k <= intervals
  AxisMask moving = 0;  ///< axes whose control points are not all equal (the rest are constant)
  std::uint8_t intervals = kTable;  ///< table intervals used: kBlendTable or kTable
};

}  // namespace geom

/// line and arc: closed form; blend: quintic Bezier of a tolerance ball; spline: one piece of an
/// Akima or B-spline (#SPLINE), a cubic held as its degree-elevated quintic Bezier (spline.hpp).
/// Samples (uniform in the curve parameter) for the derivative bounds of a spline piece.
inline constexpr std::size_t kSplineBoundSamples = 1024;

/// The Bezier curves' arc-length tables and the bounds of a whole blend (Segment::bounds) run in
/// an AVX2 build of their loops where the CPU has AVX2 and this is allowed (the default): the
/// same values to the bit as the baseline build, in about half the instructions
/// (path_bezier.cpp). Tests switch it off to compare both.
bool wide_loops_available() noexcept;
void allow_wide_loops(bool allowed) noexcept;

enum class SegmentKind : std::uint8_t { line, arc, blend, spline };

/// One curve with arc-length parametrisation, restricted to a window [s_lo, s_hi] of its
/// underlying geometry (trimming for tolerance balls moves the window, not the geometry).
class Segment {
 public:
  using LineGeom = geom::LineGeom;
  using ArcGeom = geom::ArcGeom;
  using BezierGeom = geom::BezierGeom;

  /// An empty segment (a line of length 0).
  Segment() = default;
  /// A line from `a` to `b`; `metric` selects the axes that measure the length.
  static Segment line(std::uint8_t axis_count, AxisMask metric, const AxisVec& a, const AxisVec& b);
  /// An arc or helix from the Move (plane from Arc, principal or general; other axes move
  /// linearly in s). A spline Move (Move::spline) is not an arc: use from_move().
  static Segment arc(const Move& move);
  /// Line, arc/helix or cubic spline piece as the Move says.
  static Segment from_move(const Move& move);
  /// A quintic Bezier curve through control points p[0..5] (used by tolerance balls).
  static Segment bezier(std::uint8_t axis_count, AxisMask metric, const std::array<AxisVec, 6>& p);
  /// The same for a blend whose ends lie at different distances from the corner (DIST with
  /// PRE_DIST != POST_DIST): its speed varies like a spline piece's, so it gets their
  /// 32-interval arc-length table and 1024 bound samples (docs/planner.md "DIST").
  static Segment bezier_uneven(std::uint8_t axis_count, AxisMask metric,
                               const std::array<AxisVec, 6>& p);
  /// A cubic Bezier piece of a spline through control points c[0..3], held exactly as its
  /// degree-elevated quintic (same arc-length machinery as blends); kind() == spline.
  static Segment cubic(std::uint8_t axis_count, AxisMask metric, const std::array<AxisVec, 4>& c);

  SegmentKind kind() const noexcept;
  std::uint8_t axis_count() const noexcept { return n_; }
  AxisMask metric() const noexcept { return metric_; }
  double length() const noexcept { return s_hi_ - s_lo_; }  ///< [mm]

  /// Point and derivatives at arc length s, clamped to [0, length()].
  PathPoint at(double s) const noexcept;
  /// Position only (cheaper for lines and arcs).
  AxisVec point(double s) const noexcept;
  AxisVec start() const noexcept { return point(0.0); }
  AxisVec end() const noexcept { return point(length()); }
  /// Bounds of |x'_i|, |x''_i|, |x'''_i| over the segment (exact for lines and arcs,
  /// 65 samples plus 1 % margin for blends, 1024 for spline pieces and uneven blends:
  /// docs/planner.md "Geometry").
  DerivativeBounds bounds() const noexcept;
  /// The same curve restricted to [s0, s1] (0 <= s0 < s1 <= length()).
  Segment trimmed(double s0, double s1) const noexcept;

  /// Norm of v over the metric axes.
  double metric_norm(const AxisVec& v) const noexcept;

 private:
  PathPoint at_raw(double s) const noexcept;
  AxisVec point_raw(double s) const noexcept;
  PathPoint bezier_at(const BezierGeom& g, double s) const noexcept;    // path_bezier.cpp
  double bezier_t(const BezierGeom& g, double s) const noexcept;        // s -> t
  PathPoint bezier_at_t(const BezierGeom& g, double t) const noexcept;  // at curve parameter t
  DerivativeBounds bezier_bounds() const noexcept;                      // path_bezier.cpp
  /// A Bezier segment whose arc-length table has `intervals` intervals (kBlendTable, kTable).
  static Segment bezier_with(std::uint8_t axis_count, AxisMask metric,
                             const std::array<AxisVec, 6>& p, int intervals);

  std::variant<LineGeom, ArcGeom, BezierGeom> geom_;
  std::uint8_t n_ = 0;
  AxisMask metric_ = 0;
  double s_lo_ = 0.0;    ///< window start in the underlying geometry [mm]
  double s_hi_ = 0.0;    ///< window end [mm]
  bool spline_ = false;  ///< a Bezier that is a spline piece, not a blend
  bool fine_ = false;    ///< a blend sampled as finely as a spline piece (bezier_uneven)
};

/// The metric of a cubic spline piece with control points c: the path axes if its control
/// polygon moves them, else every axis (spline.hpp).
AxisMask polygon_metric(std::uint8_t axis_count, AxisMask path_axes,
                        const std::array<AxisVec, 4>& c);

/// The metric used for a displacement: the path axes if they move, else every axis.
AxisMask effective_metric(std::uint8_t axis_count, AxisMask path_axes, const AxisVec& delta);

}  // namespace ncsim::planner

#pragma once
// tracking/caxtrack: automatic tangential tracking of a rotary axis, #CAXTRACK ON / OFF
// (isg-language.md §5.7, PROG-207450507; seed 004 §4.10; docs/caxtrack.md).
//
// Purpose: give every path block the tracking axis's (C's) values so that C stays tangential
// to the path in the XY plane plus OFFSET, before the planner plans the block: C is then an
// ordinary axis of the Move and the planner keeps its dynamics (the path slows where C cannot
// follow; the audit checks C like any axis).
// Inputs: the Moves in MCS (interpolated-axis order), the X, Y and tracking-axis slots, the
// #CAXTRACK ON values (ANGLIMIT, OFFSET, ROTMODE) and the tracking axis's position at ON.
// Outputs: per Move the Move with C set, preceded by a C-only turn Move (G00 slope, the path
// stands) when the tangent turns by more than ANGLIMIT at the block joint.
// Method (decisions in docs/caxtrack.md):
//   angle   C = theta + OFFSET (ROTMODE 0: the axis turns the tool) or C = OFFSET - theta
//           (ROTMODE 1: the axis turns the workpiece, P-CHAN-00185 semantics), theta the
//           tangent angle atan2(dY, dX) [deg]; C is unwrapped: of the angles equal modulo 360
//           the one nearest to the axis's current value.
//   line    C constant along the block (the tangent is).
//   arc     (G17 only) C linear in the arc angle: exactly the tangent.
//   spline  C a cubic Bezier in the piece's own parameter that meets the tangent angle at
//           u = 0, 1/3, 2/3, 1; pieces are halved (de Casteljau, exact) until the fit is within
//           kFitTolerance at the sample points.
//   joint   the tangent change at a block joint (against the C the last block ended with):
//           above ANGLIMIT a C-only turn block is inserted before the block (ISG: "the path
//           movement is halted and the dressing movement is performed by an inserted motion
//           block at rapid traverse rate"); at or below ANGLIMIT the turn is shared out over
//           the block (C moves from the old to the new value with the block's parameter:
//           "the dressing movement will start immediately with transition to the second
//           block"). The first block after ON is a joint against the axis's position at ON.
//   no XY   a block without XY motion keeps C.
// Invariants: pure values and a small state (the current C); no allocation beyond the output
// vector; throws nothing but std::bad_alloc.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "planner/move.hpp"

namespace ncsim::tracking {

/// Fit tolerance of C on a spline piece [deg] (at the sample points of each half).
inline constexpr double kCaxFitTolerance = 0.01;

/// #CAXTRACK ON values the tracker uses.
struct CaxTrackParams {
  double anglimit = 0.0;  ///< ANGLIMIT [deg], >= 0: larger joint turns stop the path
  double offset = 0.0;    ///< OFFSET [deg]: angle between tangent and axis
  int rotmode = 0;        ///< ROTMODE: 0 the axis turns the tool, 1 the workpiece
};

/// Tangent angle [deg] in (-180, 180] of the XY direction (dx, dy); nullopt when both are ~0.
std::optional<double> tangent_angle(double dx, double dy) noexcept;
/// The angle equal to `angle` modulo 360 nearest to `near` [deg].
double unwrap_near(double angle, double near) noexcept;
/// The tracking axis's value for tangent angle `theta` [deg] (before unwrapping).
double tracking_value(const CaxTrackParams& p, double theta) noexcept;

/// Splits a spline Move at u = 0.5 (de Casteljau on every axis): the two halves, each a spline
/// Move with the same modal fields.
std::pair<planner::Move, planner::Move> split_spline(const planner::Move& mv);
/// Start and end XY tangent of `mv` (x, y the interpolated slots) [deg]; nullopt without XY
/// motion.
std::optional<std::pair<double, double>> move_tangents(const planner::Move& mv, int x, int y);

/// What tracking a Move gave.
struct CaxOutcome {
  std::vector<planner::Move> moves;  ///< the turn block (if any) and the block (or its halves)
  bool turned = false;               ///< a C-only turn block was inserted (the path stops)
  double joint_turn = 0.0;           ///< |C change| at the joint [deg]
  std::string error;                 ///< non-empty: not supported (arc outside G17, ...)
};

class CaxTracker {
 public:
  /// Tracking on: axis slot `c`, XY slots `x`, `y`, the axis's current value `c_now` [deg].
  CaxTracker(const CaxTrackParams& params, int x, int y, int c, double c_now) noexcept
      : p_(params), x_(x), y_(y), c_(c), c_now_(c_now) {}

  /// The Move(s) for `mv` with the tracking axis set (mv's own C values are replaced).
  CaxOutcome track(const planner::Move& mv);
  double current() const noexcept { return c_now_; }  ///< C after the last Move [deg]
  int axis() const noexcept { return c_; }            ///< the tracking axis's slot
  const CaxTrackParams& params() const noexcept { return p_; }

 private:
  /// Sets C on a spline piece (`c_start` the unwrapped tracking value at its start, the
  /// shared-out joint turn shift0 at u = 0 falling to shift1 at u = 1 [deg]); appends the
  /// piece or its halves to `out`.
  void fit_spline(const planner::Move& mv, double c_start, double shift0, double shift1, int depth,
                  std::vector<planner::Move>& out);

  CaxTrackParams p_;
  int x_ = 0, y_ = 1, c_ = 3;
  double c_now_ = 0.0;  ///< [deg]
};

}  // namespace ncsim::tracking

#pragma once
// program/move_builder: a Motion command as a planner::Move (docs/ipo.md "From program to
// cycles").
//
// Purpose: the one place where the interpreter's motion becomes the planner's Move: in the
// interpolated-axis order and in MCS (CsFrames), with the modal state of its block (transition,
// exact stop, contour, slope, dynamics weights; converted once per change), checked before it
// moves (soft limits when refused, the kinematic's workspace under #TRAFO ON) and, in PCS1,
// with the belt's share (of the joints under #TRAFO ON, TrafoPath; else the velocity split,
// BeltSplit).
// Inputs: Motion commands and spline vertices with their line (the file: SourceErrors::file()).
// Outputs: planner::Move values; program errors through SourceErrors (NC6001, NC4601 when
// refused, NC3201 / NC3202, NC6211).
// Invariants: a Move never names a non-interpolated axis; the weights are shared between Moves
// of equal settings.

#include <cstdint>
#include <memory>
#include <span>

#include "interp/command.hpp"
#include "machines/machine.hpp"
#include "planner/move.hpp"
#include "program/belt_split.hpp"
#include "program/cs_frames.hpp"
#include "program/machine_axes.hpp"
#include "program/source_errors.hpp"
#include "program/trafo_path.hpp"

namespace ncsim::program {

/// A block's planner weights (planner::AxisWeights) from the interpreter's, for the
/// interpolated machine axes `axes`, of a G00 block when `rapid`; null when all are 100 %.
std::shared_ptr<const planner::AxisWeights> axis_weights(const interp::DynamicsWeights& w,
                                                         std::span<const std::uint8_t> axes,
                                                         bool rapid);

/// The parts a MoveBuilder reads; all must outlive it.
struct MoveParts {
  const machines::Machine& machine;
  const AxisLayout& layout;
  SourceErrors& errors;
  const CsFrames& frames;
  const TrafoPath& trafo;
  const BeltSplit& belt;
};

class MoveBuilder {
 public:
  /// `refuse_soft_limits`: a block whose programmed target (or arc extent, spline point) in the
  /// MCS without kinematics lies beyond the soft limits is refused before it moves, with
  /// `check`'s NC4601 at its line (interp::add_soft_limit_errors).
  MoveBuilder(const MoveParts& parts, bool refuse_soft_limits) noexcept
      : parts_(parts), refuse_soft_limits_(refuse_soft_limits) {}

  /// The Move of Motion `m` at `line`.
  planner::Move to_move(const interp::Motion& m, std::uint32_t line);
  /// The modal fields of a Move from the block's snapshot (transition, contour, slope, ...).
  void set_modal(const interp::ModalSnapshot& s, planner::Move& mv, std::uint32_t line);
  /// A spline vertex's checks: no non-interpolated axis, the soft limits when refused.
  void check_vertex(const interp::SplinePoint& p, std::uint32_t line) const;
  /// The belt's share of a Move programmed in PCS1: of the joints under #TRAFO ON, else the
  /// symmetric limit (arcs, splines: their tangent turns) or the split of a line.
  void pcs1_share(planner::Move& mv) const;

 private:
  /// The first of check's NC4601 errors of `c` ends the stream at its line.
  void check_soft_limits(const interp::Command& c) const;

  MoveParts parts_;
  bool refuse_soft_limits_;
  /// Dynamics weightings (docs/interp.md "Dynamics weighting"): the interpreter's last, and
  /// the planner's for feed and G00 blocks (interpolated order), made once per change.
  std::shared_ptr<const interp::DynamicsWeights> weights_src_;
  std::shared_ptr<const planner::AxisWeights> weights_feed_;
  std::shared_ptr<const planner::AxisWeights> weights_rapid_;
};

}  // namespace ncsim::program

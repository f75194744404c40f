#pragma once
// program/spline_section: #SPLINE sections at the adapter (docs/ipo.md "Splines at the
// adapter").
//
// Purpose: SplineBegin opens a planner::SplineBuilder (Akima or B-spline, the interpolated
// axes, the path axes) whose first vertex is the section's start; each SplinePoint adds its
// vertex (in MCS: a section under #CS goes through the frame like any motion; Akima's weights
// and the B-spline's blossoms commute with a rigid frame, so the curve is the frame's image of
// the PCS curve) with its own line and feed; SplineEnd finishes the section. Every completed
// piece becomes one spline Move (planner::spline_move: cubic Bezier, planned with arc-length
// parametrisation, never chopped; a near-cusp in parts of its own, planner::split_near_cusp)
// carrying the modal state of the #SPLINE ON block; in PCS1 it first gets the belt's share
// (MoveBuilder::pcs1_share), then it leaves through PathOutput::emit().
// Inputs: SplineBegin / SplinePoint / SplineEnd with their line.
// Outputs: spline Moves into PathOutput, in curve order.
// Invariants: the builder holds a window of 8 points and one command completes at most 4
// pieces: memory does not grow with the section.

#include <cstdint>
#include <optional>
#include <span>

#include "interp/command.hpp"
#include "planner/move.hpp"
#include "planner/spline.hpp"
#include "program/cs_frames.hpp"
#include "program/machine_axes.hpp"
#include "program/move_builder.hpp"
#include "program/path_output.hpp"
#include "program/source_errors.hpp"

namespace ncsim::program {

class SplineSection {
 public:
  /// All arguments must outlive this.
  SplineSection(const AxisLayout& layout, SourceErrors& errors, const CsFrames& frames,
                MoveBuilder& moves, PathOutput& output) noexcept
      : layout_(layout), errors_(errors), frames_(frames), moves_(moves), output_(output) {}

  /// #SPLINE ON: opens a section (NC6001 inside an open one).
  void begin(const interp::SplineBegin& b, std::uint32_t line);
  /// A vertex of the open section (NC6001 outside one).
  void point(const interp::SplinePoint& p, std::uint32_t line);
  /// #SPLINE OFF: the section's last pieces (NC6001 without an open one).
  void end(std::uint32_t line);

 private:
  void queue_pieces(std::span<const planner::SplinePiece> pieces);
  /// One piece (or a part of it) as a Move into PathOutput.
  void queue_piece(const planner::SplinePiece& piece);

  const AxisLayout& layout_;
  SourceErrors& errors_;
  const CsFrames& frames_;
  MoveBuilder& moves_;
  PathOutput& output_;
  std::optional<planner::SplineBuilder> builder_;  ///< the open section's
  planner::Move modal_;                            ///< the #SPLINE ON block's modal Move
  bool pcs1_ = false;  ///< the open section is programmed in PCS1 (its pieces get the belt's)
};

}  // namespace ncsim::program

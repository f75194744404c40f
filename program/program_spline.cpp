// program/program_spline: #SPLINE sections at the adapter (docs/ipo.md "Splines at the adapter").
//
// SplineBegin opens a planner::SplineBuilder (Akima or B-spline, the interpolated axes, the
// path axes) whose first vertex is the section's start; each SplinePoint adds its vertex (in MCS:
// a section under #CS goes through the frame like any motion; Akima's weights and the B-spline's
// blossoms commute with a rigid frame, so the curve is the frame's image of the PCS curve) with
// its own line and feed; SplineEnd finishes the section. Every completed piece becomes one
// spline Move (planner::spline_move: cubic Bezier, planned with arc-length parametrisation,
// never chopped) carrying the modal state of the #SPLINE ON block; it leaves through
// emit_path() (program_static.cpp: #CAXTRACK, the static unit's belt feed may halve it); in
// PCS1 it first gets the belt's share: of the joints under #TRAFO ON (reserve_belt_share), else
// the PCS1 velocity split on the axes (Move::belt). The builder holds a window of 8 points and
// the queue the parts of at most 4 pieces: memory does not grow with the section.

#include <string>
#include <utility>
#include <vector>

#include "program/program_source.hpp"

namespace ncsim::ipo {

void ProgramSource::spline_begin(const interp::SplineBegin& b, std::uint32_t line) {
  if (spline_) fail(line, "#SPLINE ON inside an open spline section");
  spline_modal_ = planner::Move{};
  spline_modal_.axis_count = static_cast<std::uint8_t>(axes_.size());
  spline_modal_.path_axes = path_axes_;
  set_modal(b.modal, spline_modal_, line);
  spline_pcs1_ = b.frame.space == interp::Space::pcs1;
  const planner::SplineType type = b.type == interp::SplineType::bspline
                                       ? planner::SplineType::bspline
                                       : planner::SplineType::akima;
  spline_.emplace(type, static_cast<std::uint8_t>(axes_.size()), path_axes_);
  // The start vertex carries no feed: no piece takes its feed from it (spline.hpp).
  queue_pieces(spline_->push({to_mcs(b.frame, b.start, line), line, 0.0}));
}

void ProgramSource::spline_point(const interp::SplinePoint& p, std::uint32_t line) {
  if (!spline_) fail(line, "spline point outside a spline section");
  for (std::size_t i = 0; i < machine_.axes.size(); ++i) {
    if (slot_[i] < 0 && ((p.programmed >> i) & 1u) != 0) {
      fail(line, "spline point on axis " + machine_.axes[i].name +
                     " (spindle / conveyor axes are not path-interpolated)");
    }
  }
  // issue 34 item 22: check's NC4601 for a vertex, refused before the section moves on
  if (refuse_soft_limits_ && p.frame == interp::CoordFrame{})
    check_soft_limits(interp::Command{line, file_, p});
  queue_pieces(spline_->push({to_mcs(p.frame, p.point, line), line, p.feed}));
}

void ProgramSource::spline_end(std::uint32_t line) {
  if (!spline_) fail(line, "#SPLINE OFF without an open spline section");
  queue_pieces(spline_->finish());
  spline_.reset();
}

void ProgramSource::queue_pieces(std::span<const planner::SplinePiece> pieces) {
  // The queue is empty before each command (pull() hands it out first); one command completes
  // at most 4 pieces (SplineBuilder::finish()), each of which emit_path() may split.
  for (const planner::SplinePiece& whole : pieces) {
    // issue 34 item 12: a near-cusp runs slowly in its own parts, not the whole piece
    const std::vector<planner::SplinePiece> parts = planner::split_near_cusp(whole, path_axes_);
    if (parts.empty()) queue_piece(whole);
    for (const planner::SplinePiece& part : parts)
      queue_piece(part);
  }
}

void ProgramSource::queue_piece(const planner::SplinePiece& piece) {
  planner::Move mv = planner::spline_move(piece, spline_modal_);
  mv.file = file_;  // --- conveyor-tail: Moves carry their file (next())
  // A piece in PCS1 runs with the belt on top as a line does (ProgramSource::to_move): under
  // #TRAFO ON belt_share samples the piece's curve (docs/conveyor.md "Machining in PCS1"),
  // else the axes get the PCS1 velocity split (S-5).
  if (spline_pcs1_) {
    if (mv.transformed)
      reserve_belt_share(mv);
    else
      mv.belt = belt_;
  }
  emit_path(std::move(mv));
}

}  // namespace ncsim::ipo

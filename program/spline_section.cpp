#include "program/spline_section.hpp"

#include <string>
#include <utility>
#include <vector>

namespace ncsim::program {

void SplineSection::begin(const interp::SplineBegin& b, std::uint32_t line) {
  if (builder_) errors_.not_supported(line, "#SPLINE ON inside an open spline section");
  modal_ = planner::Move{};
  modal_.axis_count = layout_.count();
  modal_.path_axes = layout_.path_axes;
  moves_.set_modal(b.modal, modal_, line);
  pcs1_ = b.frame.space == interp::Space::pcs1;
  const planner::SplineType type = b.type == interp::SplineType::bspline
                                       ? planner::SplineType::bspline
                                       : planner::SplineType::akima;
  builder_.emplace(type, layout_.count(), layout_.path_axes);
  // The start vertex carries no feed: no piece takes its feed from it (spline.hpp).
  queue_pieces(builder_->push({frames_.to_mcs(b.frame, b.start, line), line, 0.0}));
}

void SplineSection::point(const interp::SplinePoint& p, std::uint32_t line) {
  if (!builder_) errors_.not_supported(line, "spline point outside a spline section");
  moves_.check_vertex(p, line);
  queue_pieces(builder_->push({frames_.to_mcs(p.frame, p.point, line), line, p.feed}));
}

void SplineSection::end(std::uint32_t line) {
  if (!builder_) errors_.not_supported(line, "#SPLINE OFF without an open spline section");
  queue_pieces(builder_->finish());
  builder_.reset();
}

void SplineSection::queue_pieces(std::span<const planner::SplinePiece> pieces) {
  // The output's queue is empty before each command (ProgramSource::pull hands it out first);
  // one command completes at most 4 pieces (SplineBuilder::finish()), each of which the output
  // may split.
  for (const planner::SplinePiece& whole : pieces) {
    // issue 34 item 12: a near-cusp runs slowly in its own parts, not the whole piece
    const std::vector<planner::SplinePiece> parts =
        planner::split_near_cusp(whole, layout_.path_axes);
    if (parts.empty()) queue_piece(whole);
    for (const planner::SplinePiece& part : parts)
      queue_piece(part);
  }
}

void SplineSection::queue_piece(const planner::SplinePiece& piece) {
  planner::Move mv = planner::spline_move(piece, modal_);
  mv.file = errors_.file();  // Moves carry their file (ProgramSource::next)
  // A piece in PCS1 runs with the belt on top as a line does (MoveBuilder::to_move): under
  // #TRAFO ON belt_share samples the piece's curve (docs/conveyor.md "Machining in PCS1"),
  // else the axes get the PCS1 velocity split (S-5).
  if (pcs1_) moves_.pcs1_share(mv);
  output_.emit(std::move(mv));
}

}  // namespace ncsim::program

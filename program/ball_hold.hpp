#pragma once
// program/ball_hold: the tolerance ball between two transformed PCS1 blocks at the adapter
// (docs/conveyor.md "Machining in PCS1", "The ball").
//
// Purpose: a transformed PCS1 block that ends in a ball (G61 / G261) is held until the next
// command; a next Motion gets the ball built as the planner builds it, and the ball's share of
// the joints goes into the held block's (TrafoPath::reserve_ball_share); anything else releases
// the held block as it is before that command's items (ProgramSource::release_held).
// Inputs: the Moves of Motion commands (offer()), the next Motion or none (release()).
// Outputs: the held block into PathOutput::emit(), after its ball's share.
// Invariants: at most one block is held; it goes out before any later Move.

#include <optional>

#include "planner/move.hpp"
#include "program/path_output.hpp"
#include "program/trafo_path.hpp"

namespace ncsim::program {

class BallHold {
 public:
  /// `trafo` and `output` must outlive this.
  BallHold(const TrafoPath& trafo, PathOutput& output) noexcept : trafo_(trafo), output_(output) {}

  /// True while a block waits for the next Motion.
  bool holds() const noexcept { return held_.has_value(); }
  /// A Motion's Move (`pcs1`: programmed in PCS1): held when its ball needs the belt's share,
  /// else out at once. Release the held block first (release()).
  void offer(planner::Move move, bool pcs1);
  /// The held block (if any) out: with its ball's share into the next Motion `next`, or as it
  /// is when `next` is null (another command, or the next Motion's error).
  void release(const planner::Move* next);

 private:
  const TrafoPath& trafo_;
  PathOutput& output_;
  std::optional<planner::Move> held_;  ///< the block whose ball waits for the next Motion
};

}  // namespace ncsim::program

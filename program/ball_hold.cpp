#include "program/ball_hold.hpp"

#include <utility>

namespace ncsim::program {

void BallHold::offer(planner::Move move, bool pcs1) {
  if (trafo_.holds_for_ball(move, pcs1))
    held_ = std::move(move);
  else
    output_.emit(std::move(move));  // queued, handed out at the pull loop's top
}

void BallHold::release(const planner::Move* next) {
  if (!held_) return;
  planner::Move in = std::move(*held_);
  held_.reset();
  if (next != nullptr) trafo_.reserve_ball_share(in, *next);
  output_.emit(std::move(in));
}

}  // namespace ncsim::program

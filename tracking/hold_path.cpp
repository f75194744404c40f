// tracking/hold_path: the path ahead of the workspace hold, across block ends (see the header).

#include "tracking/hold_path.hpp"

#include <algorithm>

namespace ncsim::tracking {

HoldPath::HoldPath(const planner::Chain& path, double s, double feed, bool stops,
                   const HoldEntry* following, std::size_t count, int axis, double sign) noexcept
    : axis_(axis), sign_(sign) {
  const double s0 = std::clamp(s, 0.0, path.length());
  pieces_[0] = Piece{&path, s0, feed};
  cum_[0] = 0.0;
  cum_[1] = path.length() - s0;
  n_ = 1;
  stops_ = stops;
  // Nothing beyond a stop: the path stands at it (and the hold decides again when it moves).
  for (std::size_t k = 0; k < count && k < kHoldAhead && !stops_; ++k) {
    const HoldEntry& e = following[k];
    if (e.path == nullptr) break;
    pieces_[n_] = Piece{e.path, 0.0, e.feed};
    cum_[n_ + 1] = cum_[n_] + e.path->length();
    ++n_;
    stops_ = e.stops;
  }
}

double HoldPath::q(double d) noexcept {
  const auto coord = static_cast<std::size_t>(axis_);
  if (d >= known()) {
    const Piece& last = pieces_[n_ - 1];
    const double end = last.path->point(last.path->length())[coord];
    return stops_ ? end : end - sign_ * (d - known());
  }
  if (d < cum_[cursor_]) cursor_ = 0;
  while (cursor_ + 1 < n_ && d >= cum_[cursor_ + 1])
    ++cursor_;
  const Piece& p = pieces_[cursor_];
  return p.path->point(p.s0 + std::max(0.0, d - cum_[cursor_]))[coord];
}

bool HoldPath::next_block(HoldBlock& b) noexcept {
  while (block_piece_ < n_) {
    const Piece& p = pieces_[block_piece_];
    const planner::Chain& c = *p.path;
    if (!block_started_) {
      // The first block of a piece: the part that contains its start.
      block_part_ = 0;
      while (block_part_ + 1 < c.parts() && c.part_end(block_part_) <= p.s0)
        ++block_part_;
      block_started_ = true;
    }
    if (block_part_ >= c.parts()) {
      ++block_piece_;
      block_started_ = false;
      continue;
    }
    const double start = block_part_ == 0 ? 0.0 : c.part_end(block_part_ - 1);
    b.path = &c;
    b.from = std::max(start, p.s0);
    b.to = std::max(b.from, c.part_end(block_part_));
    b.ahead = cum_[block_piece_] + (b.from - p.s0);
    b.feed = p.feed;
    ++block_part_;
    return true;
  }
  return false;
}

}  // namespace ncsim::tracking

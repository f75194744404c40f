#pragma once
// ipo/segment_queue: the program side of the path interpolator.
//
// Purpose: pull the program's items from the Source, keep every programmed Move in a ring by
// token, prepare the Moves (planner::Preparer) and keep the look-ahead window
// (planner::LookAhead) full; hold the dwell or channel wait that follows the moves in the
// window; tell a BlockObserver which Moves have started, by token.
// Inputs: the Source, the axis limits (they must outlive the queue), the channel limits, the
// window size (P-CHAN-00650) and, under #TRAFO ON, the joint limits.
// Outputs: planned segments (pop()), the programmed Move of a ring token (the planner carries
// the token in Move::line), the pending dwell or wait, the end of the source.
// Invariants: the ring holds (N + 2) * 64 Moves, fixed at construction; fill() reuses only
// slots below the active segment's first token (activate()); fill() pulls at most kMaxPulls
// items and never throws (a source error or a malformed item becomes a message).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "ipo/source.hpp"
#include "planner/chain.hpp"
#include "planner/lookahead.hpp"
#include "planner/move.hpp"
#include "planner/prepare.hpp"

namespace ncsim::ipo {

class SegmentQueue {
 public:
  /// Throws std::invalid_argument (value and parameter named) on unusable limits, window,
  /// cycle, axis count or joint limits. `source` and `axes` must outlive the queue.
  SegmentQueue(Source& source, std::span<const planner::AxisLimits> axes,
               const planner::ChannelLimits& channel, std::size_t window,
               std::optional<planner::JointLimits> joints);
  SegmentQueue(const SegmentQueue&) = delete;
  SegmentQueue& operator=(const SegmentQueue&) = delete;

  /// Keeps the window full: pulls items, prepares Moves, pushes segments. False on an error
  /// (`message` says why).
  bool fill(std::string& message) noexcept;
  bool empty() const noexcept { return window_.empty(); }
  /// The next planned segment; the window must not be empty.
  planner::PlannedSegment pop() { return window_.pop(); }
  /// The look-ahead window (what is queued after the active segment).
  const planner::LookAhead& window() const noexcept { return window_; }
  /// The next pop() starts at `v` [mm/s] (planner::LookAhead::start_at). Returns the velocity set.
  double start_at(double v) noexcept { return window_.start_at(v); }
  /// The programmed Move of ring token `token` (low 32 bits).
  const planner::Move& programmed(std::uint32_t token) const noexcept {
    return ring_[token & ring_mask_];
  }
  /// The active segment begins with ring token `token`: the ring slots before it are free.
  void activate(std::uint32_t token) noexcept;
  /// Tells `observer` of the Moves up to ring token `token` not told yet.
  void report_starts_to(std::uint32_t token, BlockObserver& observer) noexcept;
  /// Tells `observer` of the blocks whose parts of `path` start in (s_from, s_to] [mm].
  void report_part_starts(const planner::Chain& path, double s_from, double s_to,
                          BlockObserver& observer) noexcept;
  /// The dwell after the moves in the window, removed (none: nullopt).
  std::optional<Dwell> take_dwell() noexcept;
  /// The channel wait after the moves in the window, removed (none: nullopt).
  std::optional<ChannelWait> take_wait() noexcept;
  /// The source has ended (its last Moves may still be in the window).
  bool source_done() const noexcept { return source_done_; }
  /// Programmed Moves the ring holds (fixed).
  std::size_t ring_capacity() const noexcept { return ring_.size(); }

 private:
  /// Takes the item just pulled: a dwell or a wait ends the window, a Move is prepared.
  bool take(std::string& message);
  /// The full token count of ring token `token` (the low 32 bits of one not older than the ring).
  std::uint64_t full_token(std::uint32_t token) const noexcept;

  Source& source_;
  planner::Preparer prep_;
  planner::LookAhead window_;
  std::vector<planner::PreparedSegment> ready_;  ///< prepared, not yet in the window
  std::size_t ready_next_ = 0;
  std::vector<planner::Move>
      ring_;  ///< programmed Moves by token (Move::line given to the planner)
  std::uint64_t ring_mask_ = 0;
  std::uint64_t next_token_ = 0;  ///< token of the next Move pulled
  std::uint64_t oldest_ = 0;      ///< first token of the active segment
  std::uint64_t reported_ = 0;    ///< tokens below this one were reported started
  Item item_;
  bool source_done_ = false;
  std::optional<Dwell> dwell_;       ///< G04 after the moves in the window
  std::optional<ChannelWait> wait_;  ///< ChannelWait after the moves in the window
};

}  // namespace ncsim::ipo

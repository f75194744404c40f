#pragma once
// tracking/hold_path: the path ahead of the workspace hold, across block ends (issue 14;
// docs/conveyor.md "Workspace: the hold methods", "Across block ends").
//
// Purpose: let the hold (tracking/workspace_hold) look at what the path runs next: the rest of the
// active look-ahead entry and the entries after it in the look-ahead window, as one stretch
// measured by the distance d >= 0 ahead of the present arc length, and block by block.
// Inputs: the active entry's chain and arc length s, up to kHoldAhead following entries (each
// its chain, programmed feed and whether the path stops at its end), the MCS coordinate index
// of the hold's axis and the sign of the conveying direction on it.
// Outputs: q(d), the PCS1 coordinate on that axis at distance d ahead; next_block(), the blocks
// (a part of an entry's chain, i.e. one NC block) in path order with their feed.
// Beyond what is known (the bound of kHoldAhead entries, or a window that ends without a stop):
// the worst case, the path runs straight against the conveying direction (|dq/ds| <= 1), so a
// prediction never misses a crossing for want of look-ahead. When the last known entry ends
// with a stop, the path stands at its end (the planner plans the window end as a stop).
// Invariants: pure evaluation on the inputs; no allocation; bounded work (kHoldAhead + 1
// entries of at most planner::Chain::kMaxParts parts).

#include <array>
#include <cstddef>

#include "planner/chain.hpp"

namespace ncsim::tracking {

/// Following look-ahead entries the hold looks at, at most.
inline constexpr std::size_t kHoldAhead = 16;

/// One look-ahead entry the path runs after the active one.
struct HoldEntry {
  const planner::Chain* path = nullptr;  ///< its chain (PCS1)
  double feed = 0.0;                     ///< its programmed feed [mm/s]
  bool stops = false;                    ///< the path stops at its end (G09, G60, a flush)
};

/// One NC block ahead: [from, to] on `path` (arc length on the chain) [mm].
struct HoldBlock {
  const planner::Chain* path = nullptr;
  double from = 0.0;   ///< [mm] on path
  double to = 0.0;     ///< [mm] on path
  double ahead = 0.0;  ///< distance from the present position to `from` [mm]
  double feed = 0.0;   ///< programmed feed of its entry [mm/s]
};

class HoldPath {
 public:
  /// The active entry (`path` at arc length `s`, feed, stop at its end) and `count` following
  /// entries (at most kHoldAhead are used); `axis` the interpolated axis of the hold, `sign`
  /// +1 when the conveying direction is +axis.
  HoldPath(const planner::Chain& path, double s, double feed, bool stops,
           const HoldEntry* following, std::size_t count, int axis, double sign) noexcept;

  /// Known length ahead [mm].
  double known() const noexcept { return cum_[n_]; }
  /// PCS1 coordinate of the hold's axis at distance d >= 0 ahead [mm] (worst case beyond
  /// what is known, see the header). Queries in increasing d are O(1) amortised.
  double q(double d) noexcept;
  /// The next block in path order (the first: the rest of the active one); false at the end
  /// of what is known.
  bool next_block(HoldBlock& b) noexcept;

 private:
  struct Piece {
    const planner::Chain* path = nullptr;
    double s0 = 0.0;  ///< arc length on path where the piece starts [mm]
    double feed = 0.0;
  };
  std::array<Piece, kHoldAhead + 1> pieces_{};
  std::array<double, kHoldAhead + 2> cum_{};  ///< distance ahead at each piece's start [mm]
  std::size_t n_ = 0;                         ///< pieces
  bool stops_ = false;                        ///< the path stops at the end of the last piece
  int axis_ = 0;
  double sign_ = 1.0;
  std::size_t cursor_ = 0;       ///< q(): piece of the last query
  std::size_t block_piece_ = 0;  ///< next_block(): piece and part of the next block
  std::size_t block_part_ = 0;
  bool block_started_ = false;
};

}  // namespace ncsim::tracking

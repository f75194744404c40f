#pragma once
// planner/chain: a run of segments joined with continuous curvature, planned as one piece.
//
// Purpose: the look-ahead sets the path acceleration to 0 at the ends of what it plans; a run
// of C2 joints that limit nothing (collinear blocks at one feed, gentle blends at the feed)
// is therefore handed to it as one Chain, so the acceleration carries through its inner joints
// (docs/planner.md "Chains").
// Inputs: Segments in path order, each starting where the previous ends.
// Outputs: the same queries as a Segment (length, at(s), point(s), start, end), over the
// concatenated arc length, plus the source line of the part at s.
// Invariants: 1 <= parts() <= kMaxParts; memory is at most kMaxParts segments, so a window of
// N chains holds at most N * kMaxParts blocks.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "planner/path.hpp"

namespace ncsim::planner {

class Chain {
 public:
  /// Most segments one chain holds.
  static constexpr std::size_t kMaxParts = 64;

  /// An empty chain (length 0).
  Chain() = default;
  /// A chain of one segment from source line `line`.
  explicit Chain(const Segment& first, std::uint32_t line = 0);

  /// Appends the parts of `next` (which starts where this ends). Aborts past kMaxParts.
  void append(const Chain& next);

  std::size_t parts() const noexcept { return parts_.size(); }
  const Segment& part(std::size_t i) const noexcept { return parts_[i].segment; }
  double length() const noexcept { return parts_.empty() ? 0.0 : parts_.back().end; }  ///< [mm]
  /// Arc length at the end of part i, from the chain start [mm].
  double part_end(std::size_t i) const noexcept { return parts_[i].end; }
  /// Source line of part i.
  std::uint32_t part_line(std::size_t i) const noexcept { return parts_[i].line; }
  std::uint8_t axis_count() const noexcept;
  AxisMask metric() const noexcept;

  /// Point and derivatives at s in [0, length()] (clamped); at an inner joint, the later part.
  PathPoint at(double s) const noexcept;
  AxisVec point(double s) const noexcept;
  AxisVec start() const noexcept { return point(0.0); }
  AxisVec end() const noexcept { return point(length()); }
  /// Source line of the part containing s.
  std::uint32_t line_at(double s) const noexcept;

 private:
  /// Index of the part containing s and s relative to that part's start.
  std::size_t locate(double& s) const noexcept;

  /// One part with what locate() and line_at() ask of it, in one vector: one allocation a
  /// chain (three vectors cost three: git history of docs/benchmarks.md, issue 12 session 24).
  struct Part {
    Segment segment;
    double end = 0.0;        ///< cumulative length at the end of the part [mm]
    std::uint32_t line = 0;  ///< source line
  };
  std::vector<Part> parts_;
};

}  // namespace ncsim::planner

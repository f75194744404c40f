#pragma once
// ipo/interpolator: the path interpolator, one interpolation cycle T per step().
//
// Purpose: turn a stream of planner::Move values (and dwells) into the cycle stream the axes
// receive: per cycle the path state s, v, a, j from the closed-form jerk-limited segment
// profiles (planner::profile / profile_at), the point on the curve for every axis, the axis
// velocity, acceleration and jerk by the chain rule, and the source line of the active block.
// Inputs: a Source the interpolator pulls from lazily (it may be endless), the axis limits
// (planner::AxisLimits), the exact-stop settings of each axis (P-AXIS-00236 window,
// P-AXIS-00532 settling time), the channel settings (cycle T) and the look-ahead window size
// (P-CHAN-00650).
// Outputs: step() returns the Cycle record of the cycle just done; an optional Sink sees every
// cycle and every joint the path passes (with its documented VELOJUMP / #TRANSVELMIN / C1 step).
// Method (docs/ipo.md): the look-ahead window is kept full (planner::Preparer +
// planner::LookAhead); the active segment's profile is evaluated at the local time t_in; a
// cycle that reaches the end of a segment carries the rest of T into the next one exactly, so
// the motion time of a program is the sum of its profile durations. Time is rounded up to
// whole cycles only where the path stands still by program: before a dwell (G04), at an exact
// stop (G60 / G360: window and settling time follow) and at the program end.
// Parts, each owned by value: SegmentQueue (source, ring of programmed Moves, preparer,
// window), Standstill (dwells, exact stops, channel waits), PathOverride (override, feed hold,
// velocity cap as set), ActiveSegment (the entry the path is on and the plan it follows),
// JointReport (joints to the Sink). step() orders them.
// Invariants: the per-cycle path never throws (errors from the source or a malformed Move end
// the stream with Status::error and a message); memory is bounded by the window (a ring of
// (N + 2) * 64 programmed Moves, N window entries, fixed at construction; the planner's chains
// hold their parts in vectors of at most 64); positions are continuous; a stop puts the axes
// on the programmed end point of its block bit for bit.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "ipo/active_segment.hpp"
#include "ipo/cycle.hpp"
#include "ipo/joint_report.hpp"
#include "ipo/override.hpp"
#include "ipo/path_override.hpp"
#include "ipo/segment_queue.hpp"
#include "ipo/source.hpp"
#include "ipo/standstill.hpp"
#include "planner/lookahead.hpp"
#include "planner/move.hpp"
#include "planner/prepare.hpp"

namespace ncsim::ipo {

struct Config {
  std::vector<planner::AxisLimits> axes;  ///< one per machine axis in use
  std::vector<ExactStop> exact_stop;      ///< one per axis (empty: defaults)
  planner::ChannelLimits channel;         ///< cycle T [s], P-CHAN-00009
  std::size_t window = 120;               ///< look-ahead entries (planner::window_size)
  AxisVec start{};                        ///< axis positions before the first move [mm | deg]
  Detail detail = Detail::axes;
  /// Channel hook (channel/channel.hpp): true makes a G60 / G360 stop wait, in exact_stop
  /// cycles, until Standstill::release_exact_stop() instead of for the settling time (the
  /// channel tests the window P-AXIS-00236 on the axes' actual positions).
  bool hold_exact_stop = false;
  /// Under a kinematic transform (#TRAFO ON): `axes` are the Cartesian X, Y, Z (...) and the
  /// path is also limited so that every joint keeps its own v, a, j (planner::Preparer::
  /// set_joints); the per-cycle joint setpoints come from ipo::JointStage (joint_stage.hpp).
  std::optional<planner::JointLimits> joints;
  OverrideType override_type = OverrideType::reduced;  ///< NCSIM-CHAN-630 (000 §7.5.6)
};

class PathInterpolator {
 public:
  /// Throws std::invalid_argument (value and parameter named) on unusable limits, window,
  /// cycle or exact-stop settings. `source` must outlive the interpolator; `sink` may be null.
  PathInterpolator(Config config, Source& source, Sink* sink = nullptr);
  PathInterpolator(const PathInterpolator&) = delete;
  PathInterpolator& operator=(const PathInterpolator&) = delete;

  /// Advances one interpolation cycle. Never throws.
  Status step() noexcept;
  /// The cycle done by the last step() that returned Status::running.
  const Cycle& cycle() const noexcept { return cycle_; }
  /// Why the stream ended with Status::error.
  const std::string& message() const noexcept { return message_; }
  double t_cycle() const noexcept { return t_; }  ///< [s]
  std::size_t axis_count() const noexcept { return axes_.size(); }
  const std::vector<planner::AxisLimits>& axes() const noexcept { return axes_; }
  /// The program side: ring of programmed Moves and look-ahead window (read only).
  const SegmentQueue& queue() const noexcept { return queue_; }
  /// Channel hooks at the standing path: exact-stop release, ChannelWait handler and release.
  Standstill& standstill() noexcept { return stand_; }
  /// Path override, feed hold and velocity cap (issue 13, 14; docs/ipo.md "Override and feed
  /// hold"): set between cycles, followed from the next step().
  PathOverride& path_override() noexcept { return override_; }
  /// Block starts (null: none); `observer` must outlive the interpolator.
  void observe_blocks(BlockObserver* observer) noexcept { observer_ = observer; }
  /// The entry the path is on (null: none yet); valid until the next step().
  const planner::PlannedSegment* active_entry() const noexcept {
    return entry_.active() ? &entry_.segment() : nullptr;
  }
  /// The k-th entry after the active one in the look-ahead window (null: none known; the
  /// workspace hold, tracking/workspace_hold.hpp).
  const planner::PreparedSegment* queued_entry(std::size_t k) const noexcept {
    return queue_.window().queued(k);
  }
  /// A path that starts moving after a catch-up (sync-feed, tracking/sync_entry.hpp): while the
  /// path holds at a ChannelWait, pulls and prepares what follows the wait into the look-ahead
  /// window (as the path's own start would), so that its first segment is known. False when
  /// the source failed (the next step() reports it).
  bool prefill() noexcept;
  /// The first segment the path will run after the hold (null: none known: a dwell, a wait or
  /// the end follows) and the highest velocity it may be entered with [mm/s].
  const planner::PreparedSegment* next_segment() const noexcept { return queue_.window().front(); }
  double next_entry_cap() const noexcept { return queue_.window().front_entry_cap(); }
  /// The path's next segment starts at `v` [mm/s] (at most next_entry_cap()), and `lag` [s]
  /// (in [0, T)) after the start of the next cycle. Returns the velocity set.
  double start_moving(double v, double lag) noexcept;

 private:
  /// Runs the standing part of a cycle: a dwell, an exact stop, a channel wait, nothing to
  /// move, or the program end give the cycle's status; nullopt when the path moves.
  std::optional<Status> stand_or_start() noexcept;
  /// Advances the path by T across segment ends: the path length covered [mm] and whether it
  /// held are added to; a status when a stop or an error ended the cycle.
  std::optional<Status> traverse(double& distance, bool& held) noexcept;
  /// Makes `next` the active entry; false (the run failed) when no plan fits.
  bool begin(planner::PlannedSegment&& next) noexcept;
  /// Fills the cycle record from the active entry's state (`distance` [mm] covered before it).
  void sample(double distance) noexcept;
  /// Ends the motion part of the cycle at a stop: axes exactly on the block's end point, the
  /// exact stop's wait set up where the block has one.
  Status stop_cycle(double distance) noexcept;
  /// Counts the motion cycle and hands it to the sink.
  Status close_cycle(bool held) noexcept;
  /// Counts the cycle and hands it to the sink.
  Status emit() noexcept;
  Status fail(const char* what) noexcept;

  std::vector<planner::AxisLimits> axes_;
  std::optional<planner::JointLimits> joints_;  ///< Config::joints
  double t_ = 0.001;                            ///< cycle T [s]
  Detail detail_ = Detail::axes;
  Sink* sink_ = nullptr;
  SegmentQueue queue_;
  Standstill stand_;
  PathOverride override_;
  ActiveSegment entry_;
  JointReport joint_report_;
  BlockObserver* observer_ = nullptr;
  double start_lag_ = 0.0;  ///< start_moving()'s lag, used by the next motion [s]
  bool finished_ = false;
  bool failed_ = false;
  Cycle cycle_;
  std::string message_;
};

}  // namespace ncsim::ipo

#pragma once
// ipo/standstill: where the path stands by program: dwells, exact stops, channel waits.
//
// Purpose: count the cycles the path stands at a G04 dwell (or a technology function's
// acknowledgement), at a G60 / G360 exact stop (settling time P-AXIS-00532, or until the
// channel releases it) and at a ChannelWait (until the channel's WaitHandler releases it), and
// write the record of each standing cycle.
// Inputs: the exact-stop settings of each axis, the cycle T, Config::hold_exact_stop; the
// dwells, waits and exact stops the interpolator reaches; the channel's release calls.
// Outputs: standing(), the standing cycles' records (activity, line, zero motion).
// Invariants: waits are whole cycles, rounded up (kCycleRounding, core/tolerance.hpp); a dwell is
// at most core::kLongestTime; nothing here throws after construction.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "ipo/cycle.hpp"
#include "ipo/source.hpp"
#include "planner/move.hpp"

namespace ncsim::ipo {

/// Exact-stop settings of one axis (G60 / G360).
struct ExactStop {
  double window = 0.01;      ///< P-AXIS-00236 exact-stop window [mm | deg], > 0
  double settle_time = 0.0;  ///< P-AXIS-00532 time the axis stays in the window [s], >= 0
};

class Standstill {
 public:
  /// `exact_stop`: one per axis (empty: defaults); `t_cycle` [s]; `hold_exact_stop`: an exact
  /// stop waits for release_exact_stop() instead of for the settling time. Throws
  /// std::invalid_argument naming the axis and parameter on an unusable setting.
  Standstill(std::vector<ExactStop> exact_stop, std::size_t axis_count, double t_cycle,
             bool hold_exact_stop);

  /// The path stands: a wait has cycles left, or the channel has not released it yet.
  bool standing() const noexcept { return wait_left_ > 0 || held_ || channel_held_; }
  /// Writes the record of a standing cycle into `c` (a starved one when not standing()) and
  /// counts one waiting cycle down. The cycle's index is not counted here.
  void stand(Cycle& c) noexcept;
  /// A G04 dwell (or a technology function's wait) starts after `index` cycles done; true
  /// when it takes cycles.
  bool start_dwell(const Dwell& dwell, std::uint64_t index) noexcept;
  /// The path has reached `wait`: the WaitHandler decides whether it holds (`c` shows the
  /// wait's line and event tag).
  void reach_wait(const ChannelWait& wait, Cycle& c) noexcept;
  /// A G60 / G360 stop at the end of the block of `c` (its motion cycle, c.programmed set):
  /// the settling time of every axis the block moved, or the channel's release.
  void start_exact_stop(const Cycle& c) noexcept;
  /// A motion cycle's block has event tag `tag`: raises c.event_tag to it and notes the rise
  /// (the output of its events; Dwell::since_output).
  void note_tag(std::uint32_t tag, Cycle& c) noexcept;

  /// Channel hook (Config::hold_exact_stop): a G60 / G360 stop is waiting for release.
  bool holding_exact_stop() const noexcept { return held_; }
  /// Channel hook: ends the exact-stop wait; the next step() goes on with the path.
  void release_exact_stop() noexcept { held_ = false; }
  /// Channel hook: who decides at a ChannelWait (null: the path goes on at once).
  void set_wait_handler(WaitHandler* handler) noexcept { wait_handler_ = handler; }
  /// The path holds at a ChannelWait.
  bool holding_channel() const noexcept { return channel_held_; }
  /// Channel hook: ends the hold at a ChannelWait; the next step() goes on with the path.
  void release_wait() noexcept { channel_held_ = false; }

 private:
  /// Whole cycles for a wait of `seconds` [s] (rounded up).
  std::uint64_t cycles_for(double seconds) const noexcept;

  std::vector<ExactStop> exact_stop_;
  double t_ = 0.001;              ///< cycle T [s]
  bool hold_exact_stop_ = false;  ///< Config::hold_exact_stop
  WaitHandler* wait_handler_ = nullptr;
  std::uint64_t wait_left_ = 0;  ///< dwell / settling cycles still to do
  bool held_ = false;            ///< an exact stop waits for release_exact_stop()
  bool channel_held_ = false;    ///< the path holds at a ChannelWait until release_wait()
  Activity wait_kind_ = Activity::dwell;
  std::uint32_t wait_line_ = 0;
  std::uint16_t wait_file_ = 0;  ///< source file of wait_line_
  /// The last rise of Cycle::event_tag by a motion: its tag and the cycle it rose in (the
  /// output of its events; Dwell::since_output)
  std::uint32_t tag_rise_ = 0;
  std::uint64_t tag_rise_index_ = 0;
};

}  // namespace ncsim::ipo

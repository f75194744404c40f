#pragma once
// audit/time: machining time of a program (`ncsim time`), by the same cycle loop as `run`.
//
// Purpose: total time and per-block times, split by what the channel did.
// Inputs: the interpolator Config (its Detail is forced to Detail::path: no points, no sinks),
// the program Source, an optional callback receiving each block as it completes.
// Outputs: TimeResult (cycles, total, split) and BlockTime records in execution order.
// Method: the PathInterpolator is stepped until the program ends; each cycle counts T for
// the line it reports (the `line` column of `run`), so the per-block times sum to the total
// and the total equals the number of cycles `run` writes times T, to the cycle (test).
// A block is a run of consecutive cycles with the same file and line (a line executed again later,
// in a loop, is a new record): memory stays bounded whatever the program length. Override and feed
// hold (issue 13, docs/ipo.md "Override and feed hold"): an optional operator callback is called
// before every cycle (it may call set_override / set_feed_hold); cycles in which the path stands by
// hold count as `held`, and each block carries the time lost to override and holds, measured on the
// path (Cycle::lost). Invariants: total == cycles * T == rapid + feed + dwell + exact_stop +
// starved + held + tech.

#include <array>
#include <cstdint>
#include <functional>
#include <string>

#include "ipo/interpolator.hpp"

namespace ncsim::audit {

/// Time by activity [s].
struct TimeSplit {
  double rapid = 0.0;       ///< G00 motion
  double feed = 0.0;        ///< G01/G02/G03 motion (blends count with their incoming block)
  double dwell = 0.0;       ///< G04
  double exact_stop = 0.0;  ///< G60 / G360 settling after the path stopped
  double starved = 0.0;     ///< waiting: the path stands for a channel event (ChannelWait:
                            ///< #SYNC IN, INDP, #WAIT INDP) or has nothing to move
  double held = 0.0;        ///< motion cycles standing by feed hold / override 0 (issue 13)
  double tech = 0.0;        ///< waiting for technology functions' acknowledgements (issue 33)
};

/// One block as executed.
struct BlockTime {
  std::uint32_t line = 0;
  std::uint16_t file = 0;        ///< source file of `line` (interp::Command::file, 0: main)
  double time = 0.0;             ///< [s]
  double distance = 0.0;         ///< path length covered [mm]
  double feed_programmed = 0.0;  ///< programmed path velocity (largest seen) [mm/s]
  double feed_reached = 0.0;     ///< largest path velocity reached [mm/s]
  /// F above what the axes allow (issue 12, isg-language.md 7.1): the lowest of the axes'
  /// velocity caps of the block's capped segments [mm/s]; 0 when F was never capped.
  double feed_cap = 0.0;
  double lost = 0.0;  ///< time lost to override and holds [s] (< 0: gained above 100 %)
  TimeSplit split;
};

struct TimeResult {
  ipo::Status status = ipo::Status::finished;  ///< finished, or error (message)
  std::string message;
  bool stopped = false;  ///< max_cycles reached before the program ended
  std::uint64_t cycles = 0;
  double total = 0.0;     ///< cycles * T [s]
  double distance = 0.0;  ///< path length [mm]
  double lost = 0.0;      ///< time lost to override and holds [s] (sum of the blocks')
  TimeSplit split;
};

/// The counting of machining_time, usable beside any loop that produces cycles (the channel
/// loop of `ncsim time` and `ncsim run`): add() every cycle, then finish().
class TimeCounter {
 public:
  explicit TimeCounter(double t_cycle, std::function<void(const BlockTime&)> on_block = {});
  /// Counts one cycle (its T goes to the line it reports).
  void add(const ipo::Cycle& c);
  /// Closes the open block record; cycles, total, distance and split of what was added
  /// (status, message and stopped are the caller's).
  TimeResult finish();

 private:
  using Counts = std::array<std::uint64_t, 7>;  // rapid .. held, tech (time.cpp)
  double t_ = 0.0;
  std::function<void(const BlockTime&)> on_block_;
  TimeResult r_;
  Counts total_{};
  BlockTime block_;
  Counts block_counts_{};
  std::uint64_t block_cycles_ = 0;
  bool open_ = false;
};
/// Called before cycle `index` (0-based): the operator (override, feed hold) of a scenario.
using Operator = std::function<void(ipo::PathInterpolator& ipo, std::uint64_t index)>;

/// Runs the program through the interpolator with the sinks off. `max_cycles` (0: none) stops
/// an endless program. Throws std::invalid_argument on an unusable Config (as the
/// interpolator does) and whatever `op` throws; program and source errors come back in
/// TimeResult.
TimeResult machining_time(ipo::Config config, ipo::Source& source,
                          const std::function<void(const BlockTime&)>& on_block = {},
                          std::uint64_t max_cycles = 0, const Operator& op = {});

}  // namespace ncsim::audit

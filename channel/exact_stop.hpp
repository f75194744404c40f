#pragma once
// channel/exact_stop: G60 / G360 exact stops on actual positions (docs/ipo.md "The channel
// loop").
//
// Purpose: from the cycle the command reaches the end of an exact-stop block, the path waits
// until every axis that moved in the block has its actual position inside its window
// P-AXIS-00236 (001 l.149-150, l.172); P-AXIS-00532 is the longest time allowed for that
// (P-ERR-70082, the axis monitor's, 001 l.150, l.157); without time monitoring
// (P-AXIS-00532 = 0) the wait ends with NC6101 after ChannelConfig::exact_stop_wait_max.
// Inputs: the interpolator holding at the block end, the cycle's setpoints, the axes'
// exact-stop windows. Outputs: the release of the interpolator's hold, which axes wait for
// which target (the monitors' input), NC6101.
// Invariants: noexcept per cycle; the limit in whole cycles, never shorter (docs/ipo.md).

#include <cstdint>
#include <optional>
#include <span>

#include "channel/axis_stage.hpp"
#include "channel/channel_types.hpp"

namespace ncsim::channel {

class ExactStopWait {
 public:
  /// Throws std::invalid_argument unless `wait_max` [s] > 0.
  ExactStopWait(double wait_max, double t_cycle);

  /// An exact stop is in progress.
  bool active() const noexcept { return active_; }
  /// The command reached the end of a G60 / G360 block in cycle `c` (001 l.149: t_1): waits
  /// for the axes the block moved (every joint of a transformed block) at `setpoints`.
  void begin(const ipo::Cycle& c, std::span<const axes::Setpoint> setpoints,
             bool transformed) noexcept;
  /// Axis i waits at the exact stop in progress.
  bool waits_for(std::size_t i) const noexcept { return active_ && ((moved_ >> i) & 1u) != 0; }
  double target(std::size_t i) const noexcept { return target_[i]; }  ///< [mm | deg]
  /// [s] waited so far at this exact stop.
  double waited() const noexcept { return static_cast<double>(waited_) * t_cycle_; }
  /// After the axes were driven in cycle `c`: true and `release` when every waiting axis is in
  /// its window; false when the wait ran out (NC6101 raised into `error`); true otherwise.
  bool check(const ipo::Cycle& c, const AxisStage& axes, bool& release,
             std::optional<RunTimeError>& error) noexcept;

 private:
  double wait_max_;                ///< [s] ChannelConfig::exact_stop_wait_max
  double t_cycle_;                 ///< [s]
  std::uint64_t wait_cycles_max_;  ///< wait_max_ in cycles
  bool active_ = false;            ///< an exact stop is in progress
  std::uint32_t moved_ = 0;        ///< bit i: axis i moved in the exact-stop block
  planner::AxisVec target_{};      ///< the block's end per axis [mm | deg]
  std::uint64_t waited_ = 0;       ///< cycles waited at this exact stop
};

}  // namespace ncsim::channel

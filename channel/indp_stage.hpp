#pragma once
// channel/indp_stage: the channel's INDP axes and technology outputs (docs/ipo.md "INDP axes
// and technology functions").
//
// Purpose: after the mapping of each cycle the INDP axes (IndpAxes, one PTP profile each) are
// stepped; an axis they own gets its INDP setpoint instead of the path's (Cycle::independent,
// the shown cycle patched), an axis the path drives is followed so that an INDP command starts
// from where (and how fast) it is. X[INDP_SYN ...], X[INDP_ASYN ...], #WAIT INDP and
// M/H/S/T/D arrive as channel events; the scenario's axis override (002 2.2) too.
// Inputs: the cycle, the AxisStage's setpoints and axis configs, the events. Outputs: the
// owned axes' setpoints, the shown cycle, the technology outputs of the step, NC6103 / NC6105.
// Invariants: noexcept; no allocation per cycle (TechOutput only for an output M/H/S/T/D).

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "channel/axis_stage.hpp"
#include "channel/channel_types.hpp"
#include "channel/event_context.hpp"
#include "channel/indp_axes.hpp"
#include "scenario/player.hpp"
#include "tracking/conveyor_sync.hpp"

namespace ncsim::channel {

class IndpStage {
 public:
  IndpStage(std::vector<IndpAxisConfig> axes, double t_cycle, const planner::AxisVec& start);

  IndpAxes& axes() noexcept { return indp_; }
  const IndpAxes& axes() const noexcept { return indp_; }
  /// After the mapping of cycle `c`: steps the INDP axes and gives each axis they own its
  /// setpoint in `axes`; `shown` the patched cycle (null: none owned). False: NC6103 raised.
  bool step(const ipo::Cycle& c, AxisStage& axes, const ipo::Cycle*& shown,
            std::optional<RunTimeError>& error) noexcept;
  /// Steps the INDP axes once for cycle `c` unless step() did (the cycles after an error).
  void step_once(const ipo::Cycle& c) noexcept;
  /// A scenario axis override: the run-time error (NC6105) it raises, if any.
  std::optional<std::pair<const char*, std::string>> set_override(const scenario::AxisOverride& o,
                                                                  const AxisStage& axes) noexcept;
  /// Event handlers: X[INDP_SYN / INDP_ASYN ...] (`sync`: the conveyor tracking, null: none),
  /// #WAIT INDP, M/H/S/T/D.
  EventOutcome command(const interp::AxisCommand& c, const AxisStage& axes,
                       const tracking::ConveyorSync* sync, const EventContext& ctx) noexcept;
  EventOutcome wait(const interp::WaitIndp& w, const AxisStage& axes) const noexcept;
  EventOutcome tech(const interp::Tech& t, const EventContext& ctx) noexcept;
  /// True when every INDP_SYN motion started is in position (the next block may start);
  /// `interruptible`: the wait is before a synchronisation (INTERRUPTIBLE motions go on).
  bool syn_done(bool interruptible, std::size_t n) noexcept;
  /// Hands the INDP axes to a catch-up / departure starting now: in position ones released,
  /// INTERRUPTIBLE INDP_SYN ones taken over moving; false while another still runs.
  bool hand_over(std::size_t n) noexcept;
  /// The technology functions output in this step, in program order.
  const std::vector<TechOutput>& tech_outputs() const noexcept { return tech_; }
  void clear_tech() noexcept { tech_.clear(); }
  /// The path has ended while INDP axes move: the next cycle, at rest after `last`.
  const ipo::Cycle& tail(const ipo::Cycle& last, double t_cycle) noexcept;

 private:
  IndpAxes indp_;
  ipo::Cycle patched_;                         ///< the cycle with the INDP axes' setpoints
  planner::AxisMask syn_ = 0;                  ///< axes of INDP_SYN motions the path waits for
  std::vector<TechOutput> tech_;               ///< technology functions output in this step
  ipo::Cycle tail_;                            ///< the cycles after the path's end
  bool in_tail_ = false;                       ///< the path has ended, INDP axes still move
  std::uint64_t stepped_ = ~std::uint64_t{0};  ///< the cycle indp_.step() last ran for
};

}  // namespace ncsim::channel

#pragma once
// channel/channel_events: the channel's events part (program/channel_event.hpp, docs/ipo.md
// "Channel events").
//
// Purpose: the events the Source hands out at their place in the program are executed here, by
// kind, in one dispatch (dispatch(): each kind goes to the part that executes it; a kind without
// one is run-time error NC6001 at the event's line). Per cycle the channel calls, in order:
// before_path() (a blocked event again; at a ChannelWait the events up to its tag, and the wait
// released once they and the INDP_SYN motions it waits for are done), riding() after the path's
// step (the events of the blocks started in the cycle) and at_end() when the path ended. The
// interpolator calls on_wait() when the path reaches a ChannelWait.
// Inputs: the Source's events; the parts that execute them (INDP axes, G74, conveyor tracking),
// bound at construction. Outputs: whether the path may go on; run-time errors through
// EventContext::fail() into the channel's error.
// Invariants: noexcept; no allocation per cycle (EventQueue's); after an error kept by the
// after-error stop nothing more is executed.

#include <cstdint>
#include <optional>

#include "channel/axis_stage.hpp"
#include "channel/channel_types.hpp"
#include "channel/conveyor_tracking.hpp"
#include "channel/event_context.hpp"
#include "channel/event_queue.hpp"
#include "channel/homing.hpp"
#include "channel/indp_stage.hpp"
#include "ipo/interpolator.hpp"
#include "program/signals.hpp"
#include "tracking/conveyor_sync.hpp"

namespace ncsim::channel {

class AfterErrorStop;

class ChannelEvents final : public ipo::WaitHandler {
 public:
  /// The references are the channel's own parts (and its Source) and must outlive this one.
  ChannelEvents(ipo::Source& source, ipo::PathInterpolator& ipo, AxisStage& axes, IndpStage& indp,
                ConveyorTracking& tracking, const std::optional<tracking::ConveyorSync>& sync,
                const AfterErrorStop& after, std::optional<RunTimeError>& error) noexcept
      : source_(source),
        ipo_(ipo),
        axes_(axes),
        indp_(indp),
        tracking_(tracking),
        sync_(sync),
        after_(after),
        error_(error) {}
  ChannelEvents(const ChannelEvents&) = delete;
  ChannelEvents& operator=(const ChannelEvents&) = delete;

  /// Before the path's step: a blocked event is dispatched again; a path holding at a
  /// ChannelWait goes on in this cycle once the events up to the wait's tag are done (and its
  /// INDP_SYN motions in position). False: an event raised a run-time error.
  bool before_path() noexcept;
  /// The events riding on the blocks started in cycle `c` (unless one blocks). False: an event
  /// raised a run-time error.
  bool riding(const ipo::Cycle& c) noexcept;
  /// The path ended: every event left (ProgramSource ends with a ChannelWait). False: an event
  /// raised a run-time error.
  bool at_end() noexcept;
  /// The path reached `wait` (inside the interpolator's step): true when its events are all
  /// done (the path goes on).
  bool on_wait(const ipo::ChannelWait& wait) noexcept override;
  /// #SIGNAL SYN and the signal waits go through `signals` (null: NC6001).
  void exchange_signals(program::SignalPort* signals) noexcept { signals_ = signals; }

 private:
  /// #SIGNAL SYN: sent in the cycle its place in the block stream is reached.
  EventOutcome signal(const interp::Signal& s, const program::ChannelEvent& e) noexcept;
  /// #WAIT SYN, or a #WAIT the decoder stopped at: done once the signal is taken; blocking
  /// while it is missing; NC6401 when the line found it can never come.
  EventOutcome signal_wait(const interp::SignalWait& w, const program::ChannelEvent& e) noexcept;
  /// Executes one event by kind (the one dispatch point).
  EventOutcome dispatch(const program::ChannelEvent& event) noexcept;
  /// EventQueue::run with dispatch(): the blocked event, then the due events up to `up_to`;
  /// false when one blocks or raised an error.
  bool run(std::uint32_t up_to) noexcept;

  ipo::Source& source_;
  ipo::PathInterpolator& ipo_;
  AxisStage& axes_;
  IndpStage& indp_;
  ConveyorTracking& tracking_;
  const std::optional<tracking::ConveyorSync>& sync_;
  const AfterErrorStop& after_;
  std::optional<RunTimeError>& error_;
  EventQueue queue_;                        ///< the events due and the one that blocks
  HomingSequence homing_;                   ///< G74
  program::SignalPort* signals_ = nullptr;  ///< the run's signal exchange
};

}  // namespace ncsim::channel

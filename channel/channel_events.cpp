// channel/channel_events: the channel's events part (see the header). Each event kind the
// channel executes gets a branch in dispatch() that calls into its part; a kind without one is
// run-time error NC6001 at the event's line.

#include "channel/channel_events.hpp"

#include <cstdlib>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "channel/after_error.hpp"
#include "program/program_source.hpp"

namespace ncsim::channel {

bool ChannelEvents::before_path() noexcept {
  if (!queue_.blocked() && !ipo_.standstill().holding_channel()) return true;
  const bool holding = ipo_.standstill().holding_channel();
  const bool done = run(holding ? queue_.wait_tag() : ipo_.cycle().event_tag);
  if (error_) return false;
  if (done && holding && indp_.syn_done(queue_.wait_interruptible(), axes_.size()))
    ipo_.standstill().release_wait();
  return true;
}

bool ChannelEvents::riding(const ipo::Cycle& c) noexcept {
  if (!queue_.blocked()) run(c.event_tag);
  return !error_;
}

bool ChannelEvents::at_end() noexcept {
  run(~std::uint32_t{0});
  return !error_;
}

bool ChannelEvents::on_wait(const ipo::ChannelWait& wait) noexcept {
  if (after_.active()) return false;  // after the error nothing more is executed
  queue_.at_wait(wait);
  return !queue_.blocked() && run(wait.tag) &&
         indp_.syn_done(queue_.wait_interruptible(), axes_.size());
}

bool ChannelEvents::run(std::uint32_t up_to) noexcept {
  return queue_.run(source_, up_to, [this](const program::ChannelEvent& e) { return dispatch(e); });
}

EventOutcome ChannelEvents::dispatch(const program::ChannelEvent& e) noexcept {
  return std::visit(
      [&](const auto& body) -> EventOutcome {
        using T = std::decay_t<decltype(body)>;
        // M/H/S/T/D, #WAIT INDP, INDP (IndpStage); G74 (HomingSequence); the conveyor
        // (ConveyorTracking)
        if constexpr (std::is_same_v<T, interp::Tech>) {
          return indp_.tech(body, EventContext(e, ipo_, error_));
        } else if constexpr (std::is_same_v<T, interp::WaitIndp>) {
          return indp_.wait(body, axes_);
        } else if constexpr (std::is_same_v<T, interp::AxisCommand>) {
          return indp_.command(body, axes_, sync_ ? &*sync_ : nullptr,
                               EventContext(e, ipo_, error_));
        } else if constexpr (std::is_same_v<T, interp::Motion>) {
          return tracking_.on_sync_motion(body, e);
        } else if constexpr (std::is_same_v<T, interp::MoveVelocity>) {
          return tracking_.on_move_velocity(body, e);
        } else if constexpr (std::is_same_v<T, interp::ProbeArm>) {
          return tracking_.on_probe_arm(body, e);
        } else if constexpr (std::is_same_v<T, interp::SyncIn>) {
          return tracking_.on_sync_in(body, e);
        } else if constexpr (std::is_same_v<T, interp::SyncOut>) {
          return tracking_.on_sync_out(body, e);
        } else if constexpr (std::is_same_v<T, interp::Homing>) {  // G74
          return homing_.step(body, axes_, indp_.axes(), EventContext(e, ipo_, error_));
        } else if constexpr (std::is_same_v<T, interp::MachineData>) {
          return tracking_.on_machine_data(body, e);
        } else if constexpr (std::is_same_v<T, interp::Signal>) {
          return signal(body, e);
        } else if constexpr (std::is_same_v<T, interp::SignalWait>) {
          return signal_wait(body, e);
        } else {
          return EventContext(e, ipo_, error_)
              .fail(program::kNotSupportedId, "not supported: this command in the channel");
        }
      },
      e.body);
}

EventOutcome ChannelEvents::signal(const interp::Signal& s,
                                   const program::ChannelEvent& e) noexcept {
  if (signals_ == nullptr)
    return EventContext(e, ipo_, error_)
        .fail(program::kNotSupportedId, "not supported: #SIGNAL SYN outside a run");
  try {
    signals_->send(s);
  } catch (...) {
    std::abort();  // out of memory keeping a signal
  }
  return EventOutcome::done;
}

EventOutcome ChannelEvents::signal_wait(const interp::SignalWait& w,
                                        const program::ChannelEvent& e) noexcept {
  const EventContext context(e, ipo_, error_);
  if (signals_ == nullptr)
    return context.fail(program::kNotSupportedId, "not supported: #WAIT SYN outside a run");
  if (const std::optional<std::string>& why = signals_->doomed())
    return context.fail(program::kSignalStuckId, *why);
  std::string order;
  bool taken = false;
  try {
    taken = signals_->take(program::SignalBlock{w, e.line, e.file}, order);
  } catch (...) {
    std::abort();  // out of memory
  }
  if (!order.empty()) return context.fail("250002", order);
  return taken ? EventOutcome::done : EventOutcome::blocking;
}

}  // namespace ncsim::channel

// channel/channel_events: the channel's one dispatch point for channel events
// (program/channel_event.hpp, docs/ipo.md "Channel events"). Each event kind the channel executes
// gets a branch here that calls into its own file; a kind without one is run-time error NC6001 at
// the event's line.

#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "channel/channel.hpp"
#include "program/program_source.hpp"

namespace ncsim::ipo {

EventOutcome Channel::dispatch(const ChannelEvent& e) noexcept {
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
        } else {
          return EventContext(e, ipo_, error_)
              .fail(kNotSupportedId, "not supported: this command in the channel");
        }
      },
      e.body);
}

bool Channel::run_events(std::uint32_t up_to) noexcept {
  return events_.run(source_, up_to, [this](const ChannelEvent& e) { return dispatch(e); });
}

bool Channel::on_wait(const ChannelWait& wait) noexcept {
  if (sync_error_) return false;  // after the error nothing more is executed
  events_.at_wait(wait);
  return !events_.blocked() && run_events(wait.tag) &&
         indp_.syn_done(events_.wait_interruptible(), axes_.size());
}

}  // namespace ncsim::ipo

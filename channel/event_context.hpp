#pragma once
// channel/event_context: what a part executing a channel event gets (docs/ipo.md "Channel
// events"): the event, the time of the cycle being computed, and the one way to fail it (a
// run-time error at the event's line). Parts return an EventOutcome.
// Invariants: noexcept; cheap to make per dispatch (three references, no allocation).

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "channel/channel_types.hpp"
#include "ipo/interpolator.hpp"
#include "program/channel_event.hpp"

namespace ncsim::channel {

/// What executing a channel event gave.
enum class EventOutcome : std::uint8_t {
  done,      ///< executed; the next event may follow
  blocking,  ///< not done yet: dispatched again next cycle, the path holds meanwhile
  error,     ///< a run-time error was raised
};

class EventContext {
 public:
  EventContext(const program::ChannelEvent& event, const ipo::PathInterpolator& ipo,
               std::optional<RunTimeError>& error) noexcept
      : event_(event), ipo_(ipo), error_(error) {}
  const program::ChannelEvent& event() const noexcept { return event_; }
  /// [s] the start of the cycle being computed (the end of the last one).
  double t() const noexcept { return static_cast<double>(ipo_.cycle().index) * ipo_.t_cycle(); }
  /// Raises run-time error `id` at the event's line, at t(); EventOutcome::error.
  EventOutcome fail(const char* id, std::string message) const noexcept {
    ipo::Cycle at = ipo_.cycle();
    at.line = event_.line;
    at.file = event_.file;
    at.t = t();
    raise(error_, id, std::move(message), at, -1);
    return EventOutcome::error;
  }

 private:
  const program::ChannelEvent& event_;
  const ipo::PathInterpolator& ipo_;
  std::optional<RunTimeError>& error_;
};

}  // namespace ncsim::channel

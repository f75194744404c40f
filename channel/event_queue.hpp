#pragma once
// channel/event_queue: the channel events due and the one that blocks (program/channel_event.hpp,
// docs/ipo.md "Channel events").
//
// Purpose: the events due (Cycle::event_tag) are taken from the Source and executed in program
// order by the channel's dispatch (the one place that knows every part); an event that is not
// done yet (EventOutcome::blocking) is kept and dispatched again first in every later run, and
// no event after it runs meanwhile. At a ChannelWait the interpolator holds the path until the
// events up to the wait's tag are done (at_wait() notes that wait).
// Inputs: the Source's events, a dispatch callable. Outputs: whether all due events are done.
// Invariants: noexcept; no allocation per cycle (the scratch event is reused; a blocked event is
// moved, not copied).

#include <cstdint>
#include <cstdlib>
#include <optional>
#include <utility>

#include "channel/event_context.hpp"
#include "ipo/interpolator.hpp"
#include "program/channel_event.hpp"

namespace ncsim::channel {

class EventQueue {
 public:
  /// An event is blocked (kept until it is done).
  bool blocked() const noexcept { return blocked_.has_value(); }
  /// The path reached `wait`: its tag and whether it is before a synchronisation.
  void at_wait(const ipo::ChannelWait& wait) noexcept {
    wait_tag_ = wait.tag;
    wait_interruptible_ = wait.interruptible;
  }
  std::uint32_t wait_tag() const noexcept { return wait_tag_; }  ///< the wait the path holds at
  /// ChannelWait::interruptible of that wait.
  bool wait_interruptible() const noexcept { return wait_interruptible_; }
  /// Dispatches the blocked event and then the due events of `source` up to `up_to`; false
  /// when one blocks (kept) or raised an error. `dispatch(const ChannelEvent&)` gives an
  /// EventOutcome.
  template <class Dispatch>
  bool run(ipo::Source& source, std::uint32_t up_to, Dispatch&& dispatch) noexcept {
    if (blocked_) {
      const EventOutcome o = dispatch(*blocked_);
      if (o != EventOutcome::done) return false;
      blocked_.reset();
    }
    try {
      while (source.take_event(up_to, event_)) {
        const EventOutcome o = dispatch(event_);
        if (o == EventOutcome::error) return false;
        if (o == EventOutcome::blocking) {
          blocked_ = std::move(event_);
          return false;
        }
      }
    } catch (...) {
      std::abort();  // out of memory moving an event: nothing sane is left
    }
    return true;
  }

 private:
  std::optional<program::ChannelEvent>
      blocked_;                      ///< an event not done yet (EventOutcome::blocking)
  std::uint32_t wait_tag_ = 0;       ///< tag of the ChannelWait the path holds at
  bool wait_interruptible_ = false;  ///< ChannelWait::interruptible of that wait
  program::ChannelEvent event_;      ///< scratch: the event being taken
};

}  // namespace ncsim::channel

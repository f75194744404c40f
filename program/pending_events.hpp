#pragma once
// program/pending_events: the channel events of the adapter, tagged in program order
// (program/channel_event.hpp, docs/ipo.md "Channel events").
//
// Purpose: numbers the commands the channel executes beside the path, keeps them until the
// channel takes them, and says where the path must stop for them: an event that needs the path
// standing makes a ChannelWait; the INDP_SYN commands of one block share one ChannelWait after
// the last of them, so their axes start together and the next block waits for all
// (isg-language.md 6.1); every other event rides on the next item (give()).
// Inputs: channel-event commands in program order. Outputs: ChannelWait items, the tags items
// carry, the events the channel takes (take()).
// Invariants: tags increase by one per event from 1; at most kMaxPendingEvents events wait for
// an item to carry them (more force a ChannelWait).

#include <cstdint>
#include <deque>
#include <optional>

#include "interp/command.hpp"
#include "ipo/interpolator.hpp"
#include "program/channel_event.hpp"

namespace ncsim::program {

class PendingEvents {
 public:
  /// Queues `body` (of `line` in `file`) with the next tag.
  void push(std::uint32_t line, std::uint16_t file, interp::CommandBody body);
  /// A ChannelWait at `line` for every event queued so far; they are given out with it.
  ipo::ChannelWait wait(std::uint32_t line) noexcept;
  /// The tag of the last event queued, given out with the next item; returns it.
  std::uint32_t give() noexcept {
    given_ = tag_;
    return tag_;
  }
  /// True when every event queued went out with an item.
  bool all_given() const noexcept { return tag_ == given_; }
  /// The oldest event with tag <= up_to into `out`, removed; false when there is none.
  bool take(std::uint32_t up_to, ChannelEvent& out);

  /// True when channel event `body` would ride on the next block: it does not stop the path, no
  /// INDP_SYN wait is open and the queue has room.
  bool rides(const interp::CommandBody& body) const noexcept;
  /// True while a block's INDP_SYN commands wait for their shared ChannelWait.
  bool syn_open() const noexcept { return syn_wait_.has_value(); }
  /// The open INDP_SYN wait goes out (true, `out` holds it) when `cmd` is not of that block
  /// (`file`: the file of the command before `cmd`).
  bool close_syn(const interp::Command& cmd, std::uint16_t file, ipo::Item& out);
  /// Queues the channel event `cmd`; true when the path stops for it (`out` holds the wait).
  bool queue(interp::Command& cmd, ipo::Item& out);

 private:
  std::deque<ChannelEvent> events_;           ///< not yet taken by the channel
  std::uint32_t tag_ = 0;                     ///< tag of the last event queued
  std::uint32_t given_ = 0;                   ///< largest tag handed out with an item
  std::optional<ipo::ChannelWait> syn_wait_;  ///< the wait after the block's INDP_SYN commands
  bool syn_interruptible_ = false;            ///< all of them INTERRUPTIBLE so far
};

}  // namespace ncsim::program

#pragma once
// program/channel_event: commands the channel executes beside the path (docs/ipo.md "Channel
// events").
//
// Purpose: the one way a command that is not path motion reaches the channel loop at the right
// point of the program: INDP axis moves, #WAIT INDP, MC_MoveVelocity, MC_TouchProbe, #SYNC IN /
// #SYNC OUT, M/H/S/T functions. program::ProgramSource numbers them with increasing tags in program
// order and keeps them in a queue; the interpolator only carries tags:
//   - an event that needs the path standing (stops_path()) becomes a ChannelWait item: the path
//     stops at the end of the block before it, the channel takes every event up to the wait's
//     tag and releases the path when they are done (ipo::WaitHandler, release_wait());
//   - any other event rides on the next Move or Dwell (planner::Move::event_tag) and is due in
//     the cycle that block starts (Cycle::event_tag: all tags up to it, so a block shorter than a
//     cycle loses none);
//   - events after the last motion of the program come as one ChannelWait before its end.
// The channel (channel/channel_events.cpp) dispatches each event by kind; a kind it cannot execute
// yet is the run-time error NC6001 `not supported: ...` at the event's line.
// Invariants: tags increase by one per event from 1; the queue holds the events between the
// interpreter and the path (bounded by the look-ahead window and kMaxPendingEvents).

#include <cstdint>

#include "interp/command.hpp"

namespace ncsim::program {

/// One command for the channel, with its place in the program.
struct ChannelEvent {
  std::uint32_t tag = 0;   ///< 1, 2, ... in program order
  std::uint32_t line = 0;  ///< source line of the command
  std::uint16_t file = 0;  ///< interp::Command::file (0: the main program)
  interp::CommandBody
      body;  ///< AxisCommand, WaitIndp, MoveVelocity, ProbeArm, SyncIn, SyncOut, Tech
};

/// Events not yet handed to the interpolator with a Move at most; more force a ChannelWait, so
/// a program of events without motion cannot grow the queue.
inline constexpr std::size_t kMaxPendingEvents = 256;

/// True when `body` is a channel event (the kinds above, and #SIGNAL SYN, #WAIT SYN; a #WAIT
/// the decoder could not answer at once is a SignalWait event too: docs/lines.md).
bool is_channel_event(const interp::CommandBody& body) noexcept;

/// True when the path must stand while `body` executes: #SYNC IN (it waits for the measured
/// value and the catch-up moves every axis), #SYNC OUT, #WAIT INDP, INDP_SYN (docs/ipo.md).
bool stops_path(const interp::CommandBody& body) noexcept;

}  // namespace ncsim::program

// channel/channel_homing: G74 in the channel (--- static-saw, docs/homing.md).
//
// Purpose: "the axis adopts the reference position P-AXIS-00152 (pos_refpkt) from the axis
// parameter list and stops" (ISG homing manual, "Commanding and execution"); the numbers after
// the axes give the order, equal numbers home together (isg-language.md l.148).
// What ncsim simulates (decision, docs/homing.md): the simulated axes have no cam and no zero
// pulse and their position is known from the start, so homing is a PTP motion of each axis
// from where it stands to P-AXIS-00152 at P-AXIS-00219 (vb_refmax, the homing travel's
// velocity; capped at P-AXIS-00212) with the axis's G01 slope (A+, A-, J), run by the INDP layer
// (channel/indp_axes.hpp); the group of the lowest order first, the next when every axis of the
// group is in position. The axis is then homed at exactly P-AXIS-00152 (a real axis stops
// beyond it by its braking distance: ncsim does not model the latch).
// Inputs: the G74 event (machine axes with order numbers), the channel's axes. Outputs: INDP
// motions; EventOutcome blocking until the last group is in position (the path stands, the
// cycles are counted on the G74 line). Errors: NC6001 for an axis that is not a channel axis;
// the INDP layer's NC5501 / NC5502 (P-AXIS-00152 beyond a soft limit) and NC6104.
// The interpreter has refused G74 with a coupling (20137), of the conveyor / an encoder axis
// (NC9104), of a spindle (NC9105) and bad order numbers (NC9106) before.
// Invariants: noexcept; no allocation per cycle (the event's axis list is the program's).

#include <cstdlib>
#include <limits>
#include <string>

#include "channel/channel.hpp"
#include "program/program_source.hpp"

namespace ncsim::ipo {

Channel::EventOutcome Channel::on_homing(const interp::Homing& command,
                                         const ChannelEvent& e) noexcept {
  const auto channel_axis = [&](std::uint8_t machine_index) {
    std::size_t i = 0;
    while (i < axes_.size() && axes_.config(i).indp.machine_index != machine_index)
      ++i;
    return i;
  };
  if (!homing_order_) {  // the event's first call: every axis must be a channel axis
    for (const auto& [axis, order] : command.axes)
      if (channel_axis(axis) == axes_.size()) {
        try {
          return event_error(kNotSupportedId,
                             "not supported: G74 of machine axis " + std::to_string(axis) +
                                 ", which is not an interpolated axis of the channel",
                             e);
        } catch (...) {
          std::abort();  // out of memory while reporting a run-time error
        }
      }
    homing_order_ = 0;
  }
  // The group running now: done when each of its axes is in position.
  for (const auto& [axis, order] : command.axes)
    if (order == *homing_order_ && !indp_.in_position(channel_axis(axis)))
      return EventOutcome::blocking;
  int next = std::numeric_limits<int>::max();
  for (const auto& [axis, order] : command.axes)
    if (order > *homing_order_ && order < next) next = order;
  if (next == std::numeric_limits<int>::max()) {
    homing_order_.reset();
    return EventOutcome::done;
  }
  homing_order_ = next;
  for (const auto& [axis, order] : command.axes) {
    if (order != next) continue;
    const std::size_t i = channel_axis(axis);
    IndpMove m;
    m.target = axes_.config(i).reference_position;
    m.feed = axes_.config(i).homing_velocity;
    if (const auto err = indp_.command(i, m)) {
      homing_order_.reset();
      return event_error(err->id.c_str(), "G74: " + err->message, e);
    }
  }
  return EventOutcome::blocking;
}

}  // namespace ncsim::ipo

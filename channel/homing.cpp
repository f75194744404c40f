// channel/homing: G74 in the channel (see the header and docs/homing.md).

#include "channel/homing.hpp"

#include <cstdlib>
#include <limits>
#include <string>

#include "program/program_source.hpp"

namespace ncsim::channel {

EventOutcome HomingSequence::step(const interp::Homing& command, const AxisStage& axes,
                                  IndpAxes& indp, const EventContext& ctx) noexcept {
  if (!order_) {  // the event's first call: every axis must be a channel axis
    for (const auto& [axis, order] : command.axes)
      if (axes.find(axis) == axes.size()) {
        try {
          return ctx.fail(program::kNotSupportedId,
                          "not supported: G74 of machine axis " + std::to_string(axis) +
                              ", which is not an interpolated axis of the channel");
        } catch (...) {
          std::abort();  // out of memory while reporting a run-time error
        }
      }
    order_ = 0;
  }
  // The group running now: done when each of its axes is in position.
  for (const auto& [axis, order] : command.axes)
    if (order == *order_ && !indp.in_position(axes.find(axis))) return EventOutcome::blocking;
  int next = std::numeric_limits<int>::max();
  for (const auto& [axis, order] : command.axes)
    if (order > *order_ && order < next) next = order;
  if (next == std::numeric_limits<int>::max()) {
    order_.reset();
    return EventOutcome::done;
  }
  order_ = next;
  for (const auto& [axis, order] : command.axes) {
    if (order != next) continue;
    const std::size_t i = axes.find(axis);
    IndpMove m;
    m.target = axes.config(i).reference_position;
    m.feed = axes.config(i).homing_velocity;
    if (const auto err = indp.command(i, m)) {
      order_.reset();
      return ctx.fail(err->id.c_str(), "G74: " + err->message);
    }
  }
  return EventOutcome::blocking;
}

}  // namespace ncsim::channel

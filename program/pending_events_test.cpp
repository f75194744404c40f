// PendingEvents: channel events get tags 1, 2, ... in program order; an event that needs the
// path standing makes a ChannelWait; a block's INDP_SYN commands share one wait after the last
// of them; events that ride along go out with the next item's tag.

#include "program/pending_events.hpp"

#include <doctest/doctest.h>

#include <variant>

namespace {

using namespace ncsim;

interp::Command command(std::uint32_t line, interp::CommandBody body) {
  return interp::Command{line, 0, std::move(body)};
}

interp::AxisCommand indp_syn(std::uint8_t axis) {
  interp::AxisCommand a;
  a.axis = axis;
  a.kind = interp::IndpKind::syn;
  return a;
}

}  // namespace

TEST_CASE("a technology function rides on the next item; #WAIT INDP stops the path") {
  program::PendingEvents events;
  ipo::Item out;
  interp::Command tech = command(3, interp::Tech{});
  CHECK(events.rides(tech.body));
  CHECK_FALSE(events.queue(tech, out));  // no stop: it rides on the next item
  CHECK_FALSE(events.all_given());
  CHECK(events.give() == 1);
  CHECK(events.all_given());
  interp::Command wait = command(4, interp::WaitIndp{});
  CHECK_FALSE(events.rides(wait.body));
  REQUIRE(events.queue(wait, out));
  const auto& w = std::get<ipo::ChannelWait>(out);
  CHECK(w.line == 4);
  CHECK(w.tag == 2);
  program::ChannelEvent e;
  CHECK(events.take(2, e));
  CHECK(e.tag == 1);
  CHECK(e.line == 3);
  CHECK(events.take(2, e));
  CHECK(e.tag == 2);
  CHECK_FALSE(events.take(2, e));
}

TEST_CASE("a block's INDP_SYN commands share one ChannelWait after the last of them") {
  program::PendingEvents events;
  ipo::Item out;
  interp::Command x = command(7, indp_syn(0));
  interp::Command y = command(7, indp_syn(1));
  CHECK_FALSE(events.queue(x, out));
  CHECK(events.syn_open());
  CHECK_FALSE(events.close_syn(y, 0, out));  // same block: the wait stays open
  CHECK_FALSE(events.queue(y, out));
  const interp::Command next = command(8, interp::Message{});
  REQUIRE(events.close_syn(next, 0, out));
  const auto& w = std::get<ipo::ChannelWait>(out);
  CHECK(w.line == 7);
  CHECK(w.tag == 2);
  CHECK_FALSE(w.interruptible);
  CHECK_FALSE(events.syn_open());
  CHECK(events.all_given());
}

TEST_CASE("more events than kMaxPendingEvents without an item force a ChannelWait") {
  program::PendingEvents events;
  ipo::Item out;
  std::size_t waits = 0;
  for (std::size_t i = 0; i < program::kMaxPendingEvents; ++i) {
    interp::Command tech = command(static_cast<std::uint32_t>(i + 1), interp::Tech{});
    if (events.queue(tech, out)) ++waits;
  }
  CHECK(waits == 1);
  CHECK(std::get<ipo::ChannelWait>(out).tag == program::kMaxPendingEvents);
  CHECK(events.all_given());
}

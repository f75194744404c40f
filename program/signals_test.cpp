// program/signals: the signal exchange of a run (docs/lines.md; PROG-207409035, PROG-207421579):
// one signal per receiver, broadcasts kept unless COUNT, a signal seen from the next cycle,
// one sender's signals used in sending order (250002), the waits that can never be answered.
#include "program/signals.hpp"

#include <doctest/doctest.h>

#include <string>

namespace {

using namespace ncsim;

interp::Signal signal(std::uint32_t id, std::vector<std::uint8_t> to,
                      std::optional<std::uint32_t> count = std::nullopt) {
  interp::Signal s;
  s.id = id;
  s.receivers = std::move(to);
  s.count = count;
  return s;
}

interp::SignalWait wait(std::uint32_t id, std::vector<std::uint8_t> from) {
  return interp::SignalWait{id, std::move(from), false};
}

}  // namespace

TEST_CASE("a signal is seen from the cycle after the one it was sent in, and used up") {
  program::SignalHub hub({1, 2});
  std::string order;
  hub.begin_cycle(0);
  interp::Signal s = signal(7, {2});
  s.params = {{0, 2.5}, {3, -1.0}};
  hub.send(1, s);
  CHECK_FALSE(hub.take(2, wait(7, {1}), order));  // same cycle: not yet
  hub.begin_cycle(1);
  const auto a = hub.take(2, wait(7, {1}), order);
  REQUIRE(a);
  CHECK(a->params[0] == 2.5);
  CHECK(a->params[3] == -1.0);
  CHECK_FALSE(a->params[1]);
  CHECK_FALSE(hub.take(2, wait(7, {1}), order));  // used up
  CHECK(order.empty());
}

TEST_CASE("CH1 CH2 sends one signal to each; a #WAIT of two senders needs both") {
  program::SignalHub hub({1, 2, 3});
  std::string order;
  hub.send(3, signal(5, {1, 2}));
  hub.begin_cycle(1);
  CHECK(hub.take(1, wait(5, {3}), order));
  CHECK(hub.take(2, wait(5, {3}), order));
  hub.send(1, signal(6, {3}));
  hub.begin_cycle(2);
  CHECK_FALSE(hub.take(3, wait(6, {1, 2}), order));  // channel 2's is missing: nothing used
  hub.send(2, signal(6, {3}));
  hub.begin_cycle(3);
  CHECK(hub.take(3, wait(6, {1, 2}), order));
}

TEST_CASE("a broadcast without COUNT stays, with COUNT it is used up after COUNT waits") {
  program::SignalHub hub({1, 2});
  std::string order;
  hub.send(1, signal(9, {}));
  hub.send(1, signal(10, {}, 2));
  hub.begin_cycle(1);
  for (int k = 0; k < 3; ++k)
    CHECK(hub.take(2, wait(9, {}), order));
  CHECK(hub.take(1, wait(10, {}), order));
  CHECK(hub.take(2, wait(10, {}), order));
  CHECK_FALSE(hub.take(2, wait(10, {}), order));
  CHECK_FALSE(hub.take(2, wait(9, {1}), order));  // a broadcast is no signal to channel 2
}

TEST_CASE("one sender's signals are waited for in the order sent, else 250002") {
  program::SignalHub hub({1, 2});
  std::string order;
  hub.send(1, signal(4711, {2}));
  hub.send(1, signal(9999, {2}));
  hub.begin_cycle(1);
  CHECK_FALSE(hub.take(2, wait(9999, {1}), order));
  CHECK(order.find("250002") != std::string::npos);
  order.clear();
  CHECK(hub.take(2, wait(4711, {1}), order));
  CHECK(hub.take(2, wait(9999, {1}), order));
  CHECK(order.empty());
}

TEST_CASE("a wait is doomed only when no channel that could answer it can still run") {
  program::SignalHub hub({1, 2, 3}, {"laser", "sorter", "robot"});
  const program::SignalBlock w2{wait(1, {1}), 12, 0};
  hub.block(2, w2);
  CHECK_FALSE(hub.mark_stuck());  // channel 1 runs
  hub.block(1, program::SignalBlock{wait(2, {3}), 4, 0});
  CHECK_FALSE(hub.mark_stuck());  // channel 3 runs: it may answer 1, which may answer 2
  hub.end(3, 30, 0);
  CHECK(hub.mark_stuck());
  REQUIRE(hub.doomed(1));
  CHECK(*hub.doomed(1) ==
        "channel 1 (laser) waits at line 4 for signal 2 of channel 3, which can never come: "
        "channel 3 (robot) ended after line 30");
  REQUIRE(hub.doomed(2));
  CHECK(hub.doomed(2)->find("channel 1 (laser) waits itself at line 4") != std::string::npos);
  hub.unblock(2);
  CHECK_FALSE(hub.doomed(2));
}

TEST_CASE("a signal on its way keeps its receiver from being doomed") {
  program::SignalHub hub({1, 2});
  hub.begin_cycle(5);
  hub.send(1, signal(3, {2}));
  hub.end(1, 9, 0);
  hub.block(2, program::SignalBlock{wait(3, {1}), 2, 0});
  CHECK_FALSE(hub.mark_stuck());  // sent in this cycle: taken in the next
}

namespace {

interp::Signal removal(std::uint32_t id, std::uint32_t id_max, bool range,
                       std::vector<std::uint8_t> ch = {}) {
  interp::Signal s;
  s.remove = true;
  s.id = id;
  s.id_max = id_max;
  s.range = range;
  s.receivers = std::move(ch);
  return s;
}

}  // namespace

TEST_CASE("#SIGNAL REMOVE clears one broadcast for ID, all of a range [PROG-207414923]") {
  program::SignalHub hub({1, 2});
  std::string order;
  hub.send(1, signal(5, {}));
  hub.send(1, signal(5, {}));
  hub.send(1, signal(3, {}));
  hub.send(1, signal(7, {}));
  hub.send(1, signal(11, {}));
  hub.begin_cycle(1);
  hub.send(2, removal(5, 5, false));  // one of the two fives
  CHECK(hub.take(2, wait(5, {}), order));
  hub.send(2, removal(5, 5, false));
  CHECK_FALSE(hub.take(2, wait(5, {}), order));
  hub.send(2, removal(1, 10, true));  // IDMIN=1 IDMAX=10: 3 and 7, not 11
  CHECK_FALSE(hub.take(2, wait(3, {}), order));
  CHECK_FALSE(hub.take(2, wait(7, {}), order));
  CHECK(hub.take(2, wait(11, {}), order));
}

TEST_CASE("#SIGNAL REMOVE with CH clears signals to that channel, not broadcasts") {
  program::SignalHub hub({1, 2, 3});
  std::string order;
  hub.send(1, signal(4, {2}));
  hub.send(1, signal(4, {3}));
  hub.send(1, signal(4, {}));
  hub.begin_cycle(1);
  hub.send(1, removal(4, 4, false, {2}));
  CHECK_FALSE(hub.take(2, wait(4, {1}), order));  // removed
  CHECK(hub.take(3, wait(4, {1}), order));        // to another channel: kept
  CHECK(hub.take(2, wait(4, {}), order));         // the broadcast: kept
}

TEST_CASE("#SIGNAL REMOVE does not see what another channel sent in the same cycle") {
  program::SignalHub hub({1, 2});
  std::string order;
  hub.begin_cycle(0);
  hub.send(1, signal(9, {}));
  hub.send(2, removal(9, 9, false));  // channel 1's signal is not seen before cycle 1
  hub.send(1, signal(8, {}));
  hub.send(1, removal(8, 8, false));  // its own: cleared
  hub.begin_cycle(1);
  CHECK(hub.take(2, wait(9, {}), order));
  CHECK_FALSE(hub.take(2, wait(8, {}), order));
}

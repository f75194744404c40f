// Standstill: dwells and settling times as whole cycles, the channel's releases, the record
// of a standing cycle, unusable exact-stop settings.

#include "ipo/standstill.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <stdexcept>
#include <string>

#include "ipo/test_support.hpp"

namespace {

using namespace ncsim;
using ipo::Activity;
using ipo::Cycle;
using ipo::Standstill;
using ipo::test::line;
using ipo::test::vec;

/// Standing cycles until the path may go on (at most `guard`).
int standing_cycles(Standstill& s, Cycle& c, int guard = 100'000) {
  int n = 0;
  while (s.standing() && n < guard) {
    s.stand(c);
    ++n;
  }
  return n;
}

struct Handler final : ipo::WaitHandler {
  bool go_on = false;
  std::uint32_t seen = 0;
  bool on_wait(const ipo::ChannelWait& wait) noexcept override {
    seen = wait.line;
    return go_on;
  }
};

}  // namespace

TEST_CASE("a dwell stands whole cycles, rounded up, and a 0 s dwell none") {
  Standstill s({}, 3, 0.001, false);
  Cycle c;
  CHECK(s.start_dwell(ipo::Dwell{0.0105, 7}, 0));
  CHECK(standing_cycles(s, c) == 11);
  CHECK(c.activity == Activity::dwell);
  CHECK(c.line == 7);
  CHECK(c.programmed == nullptr);
  CHECK_FALSE(s.start_dwell(ipo::Dwell{0.0, 8}, 11));
  CHECK_FALSE(s.standing());
  // 0.1 s at 1 ms is 100 cycles, not 101 (the rounding tolerance)
  CHECK(s.start_dwell(ipo::Dwell{0.1, 9}, 11));
  CHECK(standing_cycles(s, c) == 100);
}

TEST_CASE("a dwell counted from its events' output stands only what the motion left") {
  Standstill s({}, 3, 0.001, false);
  Cycle c;
  c.index = 40;
  s.note_tag(5, c);  // the motion of cycle 41 outputs the events of tag 5
  CHECK(c.event_tag == 5);
  ipo::Dwell d{0.02, 3, 5};
  d.since_output = true;
  CHECK(s.start_dwell(d, 50));  // 9 cycles since the output: 20 - 9 left
  CHECK(standing_cycles(s, c) == 11);
  CHECK_FALSE(s.start_dwell(d, 70));  // the whole time has passed: no cycle
  CHECK(standing_cycles(s, c) == 0);
}

TEST_CASE("an exact stop waits the longest settling time of the axes its block moved") {
  Standstill s({{0.01, 0.005}, {0.01, 0.05}, {0.01, 0.0}}, 3, 0.001, false);
  const planner::Move prog = line(vec(0, 0, 0), vec(10, 0, 0), 50.0, 4);
  Cycle c;
  c.programmed = &prog;
  c.line = 4;
  s.start_exact_stop(c);
  CHECK(standing_cycles(s, c) == 5);  // Y did not move: its 50 ms do not count
  CHECK(c.activity == Activity::exact_stop);
  CHECK(c.line == 4);
}

TEST_CASE("a held exact stop and a channel wait stand until the channel releases them") {
  Standstill s({}, 3, 0.001, true);
  const planner::Move prog = line(vec(0, 0, 0), vec(10, 0, 0), 50.0, 4);
  Cycle c;
  c.programmed = &prog;
  s.start_exact_stop(c);
  CHECK(standing_cycles(s, c, 50) == 50);
  CHECK(s.holding_exact_stop());
  s.release_exact_stop();
  CHECK_FALSE(s.standing());

  Handler handler;
  s.set_wait_handler(&handler);
  s.reach_wait(ipo::ChannelWait{12, 3}, c);
  CHECK(handler.seen == 12);
  CHECK(c.line == 12);
  CHECK(c.event_tag == 3);
  CHECK(s.holding_channel());
  s.stand(c);
  CHECK(c.activity == Activity::channel);
  s.release_wait();
  CHECK_FALSE(s.standing());
  handler.go_on = true;
  s.reach_wait(ipo::ChannelWait{13, 4}, c);
  CHECK_FALSE(s.holding_channel());
}

TEST_CASE("nothing to stand for is a starved cycle on the last line") {
  Standstill s({}, 3, 0.001, false);
  Cycle c;
  c.line = 21;
  c.distance = 1.0;
  c.path.v = 5.0;
  s.stand(c);
  CHECK(c.activity == Activity::starved);
  CHECK(c.line == 21);
  CHECK(c.distance == 0.0);
  CHECK(c.path.v == 0.0);
}

TEST_CASE("unusable exact-stop settings throw naming the axis and the parameter") {
  const auto message = [](std::vector<ipo::ExactStop> settings) {
    try {
      Standstill s(std::move(settings), 2, 0.001, false);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(message({{0.01, 0.0}}).find("1 exact-stop settings for 2 axes") != std::string::npos);
  CHECK(message({{0.01, 0.0}, {0.0, 0.0}}).find("axis 1: exact-stop window P-AXIS-00236") !=
        std::string::npos);
  CHECK(message({{0.01, -1.0}, {0.01, 0.0}}).find("axis 0: settling time P-AXIS-00532") !=
        std::string::npos);
  CHECK(message({}).empty());
}

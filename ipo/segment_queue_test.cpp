// SegmentQueue: Moves to planned segments with their programmed blocks by token, the dwell
// and the wait that end the window, zero-length lines without a ring slot, source errors as
// messages, block starts in order and once each.

#include "ipo/segment_queue.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "ipo/test_support.hpp"

namespace {

using namespace ncsim;
using ipo::SegmentQueue;
using ipo::test::axis;
using ipo::test::line;
using ipo::test::ListSource;
using ipo::test::vec;

planner::ChannelLimits channel() {
  planner::ChannelLimits ch;
  ch.t_cycle = 0.001;
  return ch;
}

struct Starts final : ipo::BlockObserver {
  std::vector<std::uint32_t> lines;
  void on_block_started(std::uint32_t line, std::uint16_t) noexcept override {
    lines.push_back(line);
  }
};

class Throwing final : public ipo::Source {
 public:
  bool next(ipo::Item&) override { throw std::runtime_error("source broke"); }
};

}  // namespace

TEST_CASE("moves become segments that lead back to their blocks; a dwell ends the window") {
  const std::vector<planner::AxisLimits> axes(3, axis(100.0, 1000.0, 1e5));
  planner::Move stop = line(vec(10, 0), vec(10, 10), 50.0, 11);
  stop.exact_stop = true;
  ListSource src({line(vec(0, 0), vec(10, 0), 50.0, 10), stop, ipo::Dwell{0.5, 12},
                  line(vec(10, 10), vec(0, 10), 50.0, 13)});
  SegmentQueue q(src, axes, channel(), 30, std::nullopt);
  std::string message;
  REQUIRE(q.fill(message));
  std::vector<std::uint32_t> lines;
  while (!q.empty()) {
    const planner::PlannedSegment s = q.pop();
    lines.push_back(q.programmed(s.segment.path.line_at(0.0)).line);
  }
  CHECK(lines == std::vector<std::uint32_t>{10, 11});
  CHECK_FALSE(q.source_done());  // the dwell stops the pulling
  const std::optional<ipo::Dwell> d = q.take_dwell();
  REQUIRE(d);
  CHECK(d->line == 12);
  CHECK_FALSE(q.take_dwell());
  REQUIRE(q.fill(message));
  REQUIRE_FALSE(q.empty());
  CHECK(q.programmed(q.pop().segment.path.line_at(0.0)).line == 13);
  CHECK(q.source_done());
}

TEST_CASE("a channel wait ends the window as a dwell does") {
  const std::vector<planner::AxisLimits> axes(3, axis(100.0, 1000.0, 1e5));
  ListSource src({line(vec(0, 0), vec(10, 0), 50.0, 1), ipo::ChannelWait{2, 7},
                  line(vec(10, 0), vec(20, 0), 50.0, 3)});
  SegmentQueue q(src, axes, channel(), 30, std::nullopt);
  std::string message;
  REQUIRE(q.fill(message));
  CHECK(q.window().size() == 1);
  const std::optional<ipo::ChannelWait> w = q.take_wait();
  REQUIRE(w);
  CHECK(w->tag == 7);
}

TEST_CASE("zero-length lines take no ring slot and reach no segment") {
  const std::vector<planner::AxisLimits> axes(3, axis(100.0, 1000.0, 1e5));
  std::vector<ipo::Item> items;
  for (std::uint32_t k = 0; k < 5000; ++k)
    items.emplace_back(line(vec(1, 1), vec(1, 1), 50.0, k));
  ListSource src(std::move(items));
  SegmentQueue q(src, axes, channel(), 30, std::nullopt);
  std::string message;
  REQUIRE(q.fill(message));  // at most 4096 pulls per fill
  CHECK(q.empty());
  CHECK_FALSE(q.source_done());
  REQUIRE(q.fill(message));
  CHECK(q.empty());
  CHECK(q.source_done());
}

TEST_CASE("source errors and unusable dwells are messages, not exceptions") {
  const std::vector<planner::AxisLimits> axes(3, axis(100.0, 1000.0, 1e5));
  std::string message;
  Throwing broken;
  SegmentQueue q1(broken, axes, channel(), 30, std::nullopt);
  CHECK_FALSE(q1.fill(message));
  CHECK(message == "source broke");
  ListSource src({ipo::Dwell{-1.0, 4}});
  SegmentQueue q2(src, axes, channel(), 30, std::nullopt);
  CHECK_FALSE(q2.fill(message));
  CHECK(message.find("G04 dwell time must be 0 .. 86400 s") != std::string::npos);
  CHECK(message.find("(line 4)") != std::string::npos);
  const std::vector<planner::AxisLimits> none;
  CHECK_THROWS_AS(SegmentQueue(src, none, channel(), 30, std::nullopt), std::invalid_argument);
}

TEST_CASE("block starts are told in order, each once") {
  const std::vector<planner::AxisLimits> axes(3, axis(100.0, 1000.0, 1e5));
  ListSource src({line(vec(0, 0), vec(10, 0), 50.0, 1), line(vec(10, 0), vec(20, 5), 50.0, 2),
                  line(vec(20, 5), vec(30, 5), 50.0, 3)});
  SegmentQueue q(src, axes, channel(), 30, std::nullopt);
  std::string message;
  REQUIRE(q.fill(message));
  Starts starts;
  while (!q.empty()) {
    const planner::PlannedSegment s = q.pop();
    const std::uint32_t token = s.segment.path.line_at(0.0);
    q.activate(token);
    q.report_starts_to(token, starts);
    q.report_part_starts(s.segment.path, 0.0, s.segment.path.length(), starts);
    q.report_starts_to(token, starts);  // told already: nothing
  }
  CHECK(starts.lines == std::vector<std::uint32_t>{1, 2, 3});
}

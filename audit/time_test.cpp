// Time: equals the cycles `run` produces, to the cycle, on seeded random programs with
// events; blocks and the split add up to the total; G60 settling shows in its block.

#include "audit/time.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "ipo/test_support.hpp"

namespace {

using namespace ncsim::audit;
using namespace ncsim::ipo;
using namespace ncsim::ipo::test;
namespace planner = ncsim::planner;

struct Counter final : Sink {
  std::uint64_t cycles = 0;
  void on_joint(const Joint&) override {}
  void on_cycle(const Cycle&) override { ++cycles; }
};

TEST_CASE("time equals the run loop to the cycle; blocks and split sum to the total") {
  std::mt19937_64 rng(99);
  for (int trial = 0; trial < 25; ++trial) {
    Config cfg;
    cfg.axes = random_limits(rng);
    cfg.channel.t_cycle = 0.00025 * static_cast<double>(1 + rng() % 16);
    cfg.exact_stop = {ExactStop{0.01, 0.003}, ExactStop{0.01, 0.0}, ExactStop{0.01, 0.01}};
    const auto items = random_program(rng, RandomProgram{});
    ListSource run_src(items);
    Counter counter;
    PathInterpolator ipo(cfg, run_src, &counter);
    while (ipo.step() == Status::running) {
    }
    ListSource time_src(items);
    double blocks = 0.0;
    std::uint64_t block_count = 0;
    const TimeResult r = machining_time(cfg, time_src, [&](const BlockTime& b) {
      blocks += b.time;
      ++block_count;
    });
    CAPTURE(trial);
    CHECK(r.status == Status::finished);
    CHECK(r.cycles == counter.cycles);
    CHECK(r.total == static_cast<double>(counter.cycles) * cfg.channel.t_cycle);
    CHECK(blocks == doctest::Approx(r.total).epsilon(1e-12));
    const TimeSplit& s = r.split;
    CHECK(s.rapid + s.feed + s.dwell + s.exact_stop + s.starved ==
          doctest::Approx(r.total).epsilon(1e-12));
    CHECK(block_count > 0);
  }
}

TEST_CASE("a G60 block shows its settling time; a dwell its time; distances are the lengths") {
  const auto ax = axis(100.0, 1000.0, 1e5);
  Config cfg;
  cfg.axes = {ax, ax, ax};
  cfg.exact_stop = {ExactStop{0.01, 0.1}, ExactStop{0.01, 0.1}, ExactStop{0.01, 0.1}};
  planner::Move g60 = line(vec(0, 0), vec(30, 0), 20.0, 1);
  g60.exact_stop = true;
  ListSource src({g60, Dwell{0.25, 2}, line(vec(30, 0), vec(30, 40), 25.0, 3)});
  std::vector<BlockTime> blocks;
  const TimeResult r = machining_time(cfg, src, [&](const BlockTime& b) { blocks.push_back(b); });
  REQUIRE(blocks.size() == 3);
  CHECK(blocks[0].line == 1);
  CHECK(blocks[0].split.exact_stop == doctest::Approx(0.1));
  CHECK(blocks[0].distance == doctest::Approx(30.0).epsilon(1e-12));
  CHECK(blocks[0].feed_reached == 20.0);
  CHECK(blocks[0].feed_programmed == 20.0);
  CHECK(blocks[1].split.dwell == doctest::Approx(0.25));
  CHECK(blocks[2].distance == doctest::Approx(40.0).epsilon(1e-12));
  CHECK(r.distance == doctest::Approx(70.0).epsilon(1e-12));
  CHECK(r.split.rapid == 0.0);
}

TEST_CASE(
    "a technology function's wait counts as tech; MVS_SNS waits only what the motion did not "
    "cover since the output") {
  const auto ax = axis(100.0, 1000.0, 1e5);
  Config cfg;
  cfg.axes = {ax, ax, ax};
  const double t = cfg.channel.t_cycle;
  for (const double d : {0.5, 3.0}) {
    CAPTURE(d);
    planner::Move mv = line(vec(0, 0), vec(30, 0), 20.0, 1);
    mv.event_tag = 1;  // the MVS_SNS function's output: when this motion starts
    ListSource src({mv, Dwell{d, 2, 1, 0, true, true}, line(vec(30, 0), vec(30, 5), 20.0, 3)});
    std::vector<BlockTime> blocks;
    const TimeResult r = machining_time(cfg, src, [&](const BlockTime& b) { blocks.push_back(b); });
    REQUIRE(r.status == Status::finished);
    const double motion = blocks[0].time;
    REQUIRE(motion > 1.5);  // 30 mm at 20 mm/s
    const double left = std::max(0.0, d - motion);
    CHECK(std::abs(r.split.tech - left) <= t + 1e-9);  // to the cycle
    CHECK(r.split.dwell == 0.0);
  }
  // A G04-like tech wait (MVS_SVS / MNS_SNS) is whole; a since-output wait with no motion of its
  // tag is whole too.
  for (const bool since : {false, true}) {
    ListSource src({line(vec(0, 0), vec(30, 0), 20.0, 1), Dwell{0.75, 2, 7, 0, true, since},
                    line(vec(30, 0), vec(30, 5), 20.0, 3)});
    const TimeResult r = machining_time(cfg, src);
    CHECK(r.split.tech == doctest::Approx(0.75));
    const TimeSplit& s = r.split;
    CHECK(s.rapid + s.feed + s.dwell + s.tech + s.exact_stop + s.starved + s.held ==
          doctest::Approx(r.total).epsilon(1e-12));
  }
}

TEST_CASE("an F above the axes' velocity is capped and the block names the cap") {
  // isg-language.md 7.1: F above what the axes allow is capped, with a note in time --blocks.
  // X and Y at 100 mm/s each: a diagonal may run at 100 sqrt(2) mm/s, a line along X at 100.
  const auto ax = axis(100.0, 1000.0, 1e5);
  Config cfg;
  cfg.axes = {ax, ax, ax};
  ListSource src({line(vec(0, 0), vec(100, 0), 250.0, 1),
                  line(vec(100, 0), vec(200, 100), 250.0, 2),
                  line(vec(200, 100), vec(250, 100), 50.0, 3)});
  std::vector<BlockTime> blocks;
  machining_time(cfg, src, [&](const BlockTime& b) { blocks.push_back(b); });
  REQUIRE(blocks.size() == 3);
  CHECK(blocks[0].feed_programmed == 250.0);
  CHECK(blocks[0].feed_cap == doctest::Approx(100.0).epsilon(1e-12));
  CHECK(blocks[0].feed_reached <= blocks[0].feed_cap * (1.0 + 1e-12));
  CHECK(blocks[1].feed_cap == doctest::Approx(100.0 * std::sqrt(2.0)).epsilon(1e-12));
  CHECK(blocks[2].feed_cap == 0.0);  // 50 mm/s is reachable
}

TEST_CASE("G00 runs at the axes' rapid velocity and its time counts as rapid") {
  auto ax = axis(100.0, 1000.0, 1e5);
  ax.v_rapid = 50.0;
  Config cfg;
  cfg.axes = {ax, ax, ax};
  planner::Move g00 = line(vec(0, 0), vec(100, 0), 0.0, 1);
  g00.rapid = true;
  ListSource src({g00, line(vec(100, 0), vec(100, 10), 20.0, 2)});
  std::vector<BlockTime> blocks;
  const TimeResult r = machining_time(cfg, src, [&](const BlockTime& b) { blocks.push_back(b); });
  REQUIRE(blocks.size() == 2);
  CHECK(blocks[0].feed_reached == 50.0);
  CHECK(blocks[0].split.feed == 0.0);
  CHECK(blocks[0].split.rapid == blocks[0].time);
  CHECK(blocks[1].split.rapid == 0.0);
  CHECK(r.split.rapid == blocks[0].time);
  CHECK(r.split.rapid + r.split.feed == r.total);
}

TEST_CASE("max_cycles stops an endless program") {
  struct Forever final : Source {
    double x = 0.0;
    bool next(Item& out) override {
      out = line(vec(x, 0), vec(x + 10.0, 0), 50.0, 1);
      x += 10.0;
      return true;
    }
  } src;
  const auto ax = axis(100.0, 1000.0, 1e5);
  Config cfg;
  cfg.axes = {ax, ax, ax};
  const TimeResult r = machining_time(cfg, src, {}, 5000);
  CHECK(r.stopped);
  CHECK(r.cycles == 5000);
}

}  // namespace

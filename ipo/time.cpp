// ipo/time: the time loop (see the header).

#include "ipo/time.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace ncsim::ipo {

namespace {

/// Cycles by activity (rapid, feed, dwell, exact stop, starved, held): integers, so the split
/// adds up to the total exactly.
using Counts = std::array<std::uint64_t, 6>;

void count(Counts& n, const Cycle& c) {
  switch (c.activity) {
    case Activity::motion:
      ++n[c.held ? 5 : c.rapid ? 0 : 1];
      break;
    case Activity::dwell:
      ++n[2];
      break;
    case Activity::exact_stop:
      ++n[3];
      break;
    case Activity::starved:
      ++n[4];
      break;
  }
}

TimeSplit split_of(const Counts& n, double t) {
  auto s = [&](std::size_t i) { return static_cast<double>(n[i]) * t; };
  return TimeSplit{s(0), s(1), s(2), s(3), s(4), s(5)};
}

}  // namespace

TimeResult machining_time(Config config, Source& source,
                          const std::function<void(const BlockTime&)>& on_block,
                          std::uint64_t max_cycles, const Operator& op) {
  config.detail = Detail::path;
  PathInterpolator ipo(std::move(config), source, nullptr);
  const double t = ipo.t_cycle();
  TimeResult r;
  Counts total{};
  BlockTime block;
  Counts block_counts{};
  std::uint64_t block_cycles = 0;
  bool open = false;
  auto close = [&] {
    block.time = static_cast<double>(block_cycles) * t;
    block.split = split_of(block_counts, t);
    on_block(block);
    open = false;
  };
  for (;;) {
    if (max_cycles != 0 && r.cycles >= max_cycles) {
      r.stopped = true;
      break;
    }
    if (op) op(ipo, r.cycles);
    const Status st = ipo.step();
    if (st != Status::running) {
      r.status = st;
      if (st == Status::error) r.message = ipo.message();
      break;
    }
    const Cycle& c = ipo.cycle();
    ++r.cycles;
    r.distance += c.distance;
    r.lost += c.lost;
    count(total, c);
    if (!on_block) continue;
    if (open && c.line != block.line) close();
    if (!open) {
      block = BlockTime{};
      block.line = c.line;
      block_counts = {};
      block_cycles = 0;
      open = true;
    }
    ++block_cycles;
    block.distance += c.distance;
    block.lost += c.lost;
    if (c.activity == Activity::motion) {
      block.feed_programmed = std::max(block.feed_programmed, c.feed);
      block.feed_reached = std::max(block.feed_reached, c.path.v);
    }
    count(block_counts, c);
  }
  if (open) close();
  r.total = static_cast<double>(r.cycles) * t;
  r.split = split_of(total, t);
  return r;
}

}  // namespace ncsim::ipo

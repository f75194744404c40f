// audit/time: the time loop (see the header).

#include "audit/time.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace ncsim::audit {

namespace {

/// Cycles by activity (rapid, feed, dwell, exact stop, starved, held, tech): integers, so the
/// split adds up to the total exactly.
using Counts = std::array<std::uint64_t, 7>;

void count(Counts& n, const ipo::Cycle& c) {
  switch (c.activity) {
    case ipo::Activity::motion:
      ++n[c.held ? 5 : c.rapid ? 0 : 1];
      break;
    case ipo::Activity::dwell:
      ++n[2];
      break;
    case ipo::Activity::exact_stop:
      ++n[3];
      break;
    case ipo::Activity::tech:
      ++n[6];
      break;
    case ipo::Activity::starved:
    case ipo::Activity::channel:  // the path stands for a channel event: "waiting" too
      ++n[4];
      break;
  }
}

TimeSplit split_of(const Counts& n, double t) {
  auto s = [&](std::size_t i) { return static_cast<double>(n[i]) * t; };
  return TimeSplit{s(0), s(1), s(2), s(3), s(4), s(5), s(6)};
}

}  // namespace

TimeCounter::TimeCounter(double t_cycle, std::function<void(const BlockTime&)> on_block)
    : t_(t_cycle), on_block_(std::move(on_block)) {}

void TimeCounter::add(const ipo::Cycle& c) {
  ++r_.cycles;
  r_.distance += c.distance;
  r_.lost += c.lost;
  count(total_, c);
  if (!on_block_) return;
  if (open_ && (c.line != block_.line || c.file != block_.file)) {
    block_.time = static_cast<double>(block_cycles_) * t_;
    block_.split = split_of(block_counts_, t_);
    on_block_(block_);
    open_ = false;
  }
  if (!open_) {
    block_ = BlockTime{};
    block_.line = c.line;
    block_.file = c.file;
    block_counts_ = {};
    block_cycles_ = 0;
    open_ = true;
  }
  ++block_cycles_;
  block_.distance += c.distance;
  block_.lost += c.lost;
  if (c.activity == ipo::Activity::motion) {
    block_.feed_programmed = std::max(block_.feed_programmed, c.feed);
    block_.feed_reached = std::max(block_.feed_reached, c.path.v);
    if (c.feed_cap > 0.0)
      block_.feed_cap = block_.feed_cap > 0.0 ? std::min(block_.feed_cap, c.feed_cap) : c.feed_cap;
  }
  count(block_counts_, c);
}

TimeResult TimeCounter::finish() {
  if (open_) {
    block_.time = static_cast<double>(block_cycles_) * t_;
    block_.split = split_of(block_counts_, t_);
    on_block_(block_);
    open_ = false;
  }
  r_.total = static_cast<double>(r_.cycles) * t_;
  r_.split = split_of(total_, t_);
  return r_;
}

TimeResult machining_time(ipo::Config config, ipo::Source& source,
                          const std::function<void(const BlockTime&)>& on_block,
                          std::uint64_t max_cycles, const Operator& op) {
  config.detail = ipo::Detail::path;
  ipo::PathInterpolator ipo(std::move(config), source, nullptr);
  TimeCounter counter(ipo.t_cycle(), on_block);
  ipo::Status status = ipo::Status::finished;
  std::string message;
  bool stopped = false;
  for (std::uint64_t n = 0;; ++n) {
    if (max_cycles != 0 && n >= max_cycles) {
      stopped = true;
      break;
    }
    if (op) op(ipo, n);
    const ipo::Status st = ipo.step();
    if (st != ipo::Status::running) {
      status = st;
      if (st == ipo::Status::error) message = ipo.message();
      break;
    }
    counter.add(ipo.cycle());
  }
  TimeResult r = counter.finish();
  r.status = status;
  r.message = std::move(message);
  r.stopped = stopped;
  return r;
}

}  // namespace ncsim::audit

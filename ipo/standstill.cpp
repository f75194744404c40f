// ipo/standstill: dwells, exact stops and channel waits (see the header).

#include "ipo/standstill.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/limits.hpp"
#include "core/number_text.hpp"
#include "core/tolerance.hpp"

namespace ncsim::ipo {

Standstill::Standstill(std::vector<ExactStop> exact_stop, std::size_t axis_count, double t_cycle,
                       bool hold_exact_stop)
    : exact_stop_(std::move(exact_stop)), t_(t_cycle), hold_exact_stop_(hold_exact_stop) {
  if (exact_stop_.empty()) exact_stop_.resize(axis_count);
  if (exact_stop_.size() != axis_count)
    throw std::invalid_argument("ipo: " + std::to_string(exact_stop_.size()) +
                                " exact-stop settings for " + std::to_string(axis_count) + " axes");
  for (std::size_t i = 0; i < exact_stop_.size(); ++i) {
    const ExactStop& e = exact_stop_[i];
    if (!(e.window > 0.0) || !std::isfinite(e.window))
      throw std::invalid_argument("ipo: axis " + std::to_string(i) +
                                  ": exact-stop window P-AXIS-00236 must be > 0, got " +
                                  core::human(e.window));
    if (!(e.settle_time >= 0.0) || !std::isfinite(e.settle_time))
      throw std::invalid_argument("ipo: axis " + std::to_string(i) +
                                  ": settling time P-AXIS-00532 must be >= 0, got " +
                                  core::human(e.settle_time));
  }
}

std::uint64_t Standstill::cycles_for(double seconds) const noexcept {
  if (!(seconds > 0.0)) return 0;
  // Dwells are at most core::kLongestTime (SegmentQueue::fill refuses longer ones), far inside
  // uint64_t.
  return static_cast<std::uint64_t>(
      std::ceil(std::min(seconds, core::kLongestTime) / t_ - kCycleRounding));
}

void Standstill::stand(Cycle& c) noexcept {
  const bool waiting = standing();
  if (wait_left_ > 0) --wait_left_;
  c.activity = waiting ? wait_kind_ : Activity::starved;
  c.line = waiting ? wait_line_ : c.line;
  c.file = waiting ? wait_file_ : c.file;
  c.path.v = c.path.a = c.path.j = 0.0;
  c.interval_jerk_limited = true;
  c.distance = 0.0;
  c.held = false;
  c.lost = 0.0;
  c.v = {};
  c.a = {};
  c.j = {};
  c.programmed = nullptr;
}

bool Standstill::start_dwell(const Dwell& dwell, std::uint64_t index) noexcept {
  wait_left_ = cycles_for(dwell.seconds);
  if (dwell.since_output && dwell.event_tag == tag_rise_) {
    const std::uint64_t since = index >= tag_rise_index_ ? index - tag_rise_index_ : 0;
    wait_left_ = wait_left_ > since ? wait_left_ - since : 0;
  }
  wait_kind_ = dwell.tech ? Activity::tech : Activity::dwell;
  wait_line_ = dwell.line;
  wait_file_ = dwell.file;
  return wait_left_ > 0;
}

void Standstill::reach_wait(const ChannelWait& wait, Cycle& c) noexcept {
  // The path stands at the end of the block before: the channel decides.
  c.event_tag = std::max(c.event_tag, wait.tag);
  c.line = wait.line;
  c.file = wait.file;
  channel_held_ = wait_handler_ != nullptr && !wait_handler_->on_wait(wait);
  wait_kind_ = Activity::channel;
  wait_line_ = wait.line;
  wait_file_ = wait.file;
}

void Standstill::start_exact_stop(const Cycle& c) noexcept {
  const planner::Move& prog = *c.programmed;
  double settle = 0.0;
  for (std::size_t i = 0; i < exact_stop_.size(); ++i) {
    bool on_arc = prog.arc && (prog.arc->axis_1 == i || prog.arc->axis_2 == i);
    if (prog.arc && prog.arc_plane)  // a plane under a rotated #CS: X, Y and Z move
      on_arc = prog.arc_plane->axes[0] == i || prog.arc_plane->axes[1] == i ||
               prog.arc_plane->axes[2] == i;
    const bool moved = prog.end[i] != prog.start[i] || on_arc;
    // The window P-AXIS-00236 is reached when the command is on the target (no following
    // error model yet; docs/ipo.md): only the settling time P-AXIS-00532 is waited for.
    if (moved) settle = std::max(settle, exact_stop_[i].settle_time);
  }
  wait_left_ = hold_exact_stop_ ? 0 : cycles_for(settle);
  held_ = hold_exact_stop_;  // the channel releases it (window on actual positions)
  wait_kind_ = Activity::exact_stop;
  wait_line_ = c.line;
  wait_file_ = c.file;
}

void Standstill::note_tag(std::uint32_t tag, Cycle& c) noexcept {
  if (tag > c.event_tag) {
    tag_rise_ = tag;
    tag_rise_index_ = c.index + 1;  // a motion cycle's record is written before it is counted
  }
  c.event_tag = std::max(c.event_tag, tag);
}

}  // namespace ncsim::ipo

#include "scenario/player.hpp"

#include <algorithm>
#include <cstdlib>
#include <type_traits>
#include <variant>

namespace ncsim::scenario {

VeStore::VeStore(const Scenario& scenario) {
  for (const VeInitial& v : scenario.ve)
    values_[v.name] = v.value;
}

void VeStore::write(const std::string& name, double value) {
  values_[name] = value;
  ++generation_;
}

std::optional<double> VeStore::read(std::string_view name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

void VeStore::answer(const std::vector<std::string>& names,
                     std::map<std::string, double>& out) const {
  for (const std::string& name : names) {
    if (const auto v = read(name)) out[name] = *v;
  }
}

Player::Player(const Scenario& scenario) : scenario_(scenario), ve_(scenario) {
  for (std::size_t i = 0; i < scenario.events.size(); ++i) {
    const Event& e = scenario.events[i];
    if (std::holds_alternative<AtTime>(e.trigger)) {
      time_events_.push_back(i);
    } else {
      lines_[std::get<AtLine>(e.trigger).line].events.push_back(i);
    }
  }
  if (scenario.stop.line) lines_[*scenario.stop.line];  // counted, no event
}

void Player::block_started(std::uint32_t line) {
  const StopConditions& stop = scenario_.stop;
  // The block before ends here: was it the last counted pass of the stop line?
  if (stop.line && current_line_ == *stop.line && passes(*stop.line) >= *stop.passes) {
    pass_stop_pending_ = true;
  }
  current_line_ = line;
  const auto it = lines_.find(line);
  if (it == lines_.end()) return;
  const std::uint32_t pass = ++it->second.passes;
  for (const std::size_t i : it->second.events) {
    if (std::get<AtLine>(scenario_.events[i].trigger).pass == pass) line_due_.push_back(i);
  }
}

void Player::apply(const Action& action) {
  std::visit(
      [this](const auto& a) {
        using T = std::decay_t<decltype(a)>;
        if constexpr (std::is_same_v<T, PathOverride>) {
          path_override_ = a.fraction;
        } else if constexpr (std::is_same_v<T, AxisOverride>) {
          axis_override_[a.axis] = a.fraction;
        } else if constexpr (std::is_same_v<T, FeedHold>) {
          feed_hold_ = a.on;
        } else if constexpr (std::is_same_v<T, ReducedFilter>) {
          reduced_filter_ = a.on;
        } else {
          ve_.write(a.name, a.value);
        }
      },
      action);
  due_.push_back(action);
}

void Player::fire(const Event& event, double t) {
  for (const Action& a : event.actions)
    apply(a);
  if (event.hold_release) {
    const Release r{t + *event.hold_release, release_seq_++};
    const auto pos = std::upper_bound(releases_.begin(), releases_.end(), r,
                                      [](const Release& x, const Release& y) {
                                        return x.t < y.t || (x.t == y.t && x.seq < y.seq);
                                      });
    releases_.insert(pos, r);
  }
}

const std::vector<Action>& Player::step(std::uint64_t cycle, double t) {
  // Broken contract of the channel loop: cycles in order, time not going back.
  if (last_cycle_ && (cycle != *last_cycle_ + 1 || t < last_t_)) std::abort();
  last_cycle_ = cycle;
  last_t_ = t;
  due_.clear();
  if (stop_) return due_;

  const StopConditions& stop = scenario_.stop;
  if (stop.time && t >= *stop.time - kTimeEpsilon) {
    stop_ = StopReason::time;
  } else if (stop.cycles && cycle >= *stop.cycles) {
    stop_ = StopReason::cycles;
  } else if (pass_stop_pending_) {
    stop_ = StopReason::line_passes;
  }
  if (stop_) {
    line_due_.clear();
    return due_;
  }

  // Hold releases first (scheduled by earlier cycles' events).
  std::size_t released = 0;
  while (released < releases_.size() && releases_[released].t <= t + kTimeEpsilon) {
    apply(FeedHold{false});
    ++released;
  }
  releases_.erase(releases_.begin(), releases_.begin() + static_cast<std::ptrdiff_t>(released));

  // Then the due events in file order: time events in time order are in file order already;
  // merge them with the line events whose pass started.
  std::vector<std::size_t>& due_events = line_due_;
  while (next_time_ < time_events_.size() &&
         std::get<AtTime>(scenario_.events[time_events_[next_time_]].trigger).t <=
             t + kTimeEpsilon) {
    due_events.push_back(time_events_[next_time_++]);
  }
  std::sort(due_events.begin(), due_events.end());
  for (const std::size_t i : due_events)
    fire(scenario_.events[i], t);
  due_events.clear();
  return due_;
}

const std::vector<Action>& Player::fire_lines() {
  due_.clear();
  if (stop_ || pass_stop_pending_) {
    line_due_.clear();
    return due_;
  }
  std::sort(line_due_.begin(), line_due_.end());
  for (const std::size_t i : line_due_)
    fire(scenario_.events[i], last_t_);
  line_due_.clear();
  return due_;
}

double Player::axis_override(std::string_view axis) const {
  const auto it = axis_override_.find(axis);
  return it == axis_override_.end() ? 1.0 : it->second;
}

std::uint32_t Player::passes(std::uint32_t line) const {
  const auto it = lines_.find(line);
  return it == lines_.end() ? 0 : it->second.passes;
}

}  // namespace ncsim::scenario

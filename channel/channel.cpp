// channel/channel: the channel loop (see the header and docs/ipo.md "The channel loop").

#include "channel/channel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <utility>
#include <variant>

#include "program/program_source.hpp"

namespace ncsim::ipo {

namespace {

Config prepared(Config config) {
  config.detail = Detail::axes;   // the axes need the point every cycle
  config.hold_exact_stop = true;  // the channel ends G60 / G360 waits on actual positions
  return config;
}

std::vector<IndpAxisConfig> indp_configs(const ChannelConfig& config) {
  std::vector<IndpAxisConfig> out;
  for (const ChannelAxis& a : config.axes)
    out.push_back(a.indp);
  return out;
}

/// `config`'s axes, when there is one per interpolated axis.
const std::vector<ChannelAxis>& checked_axes(const ChannelConfig& config, std::size_t n) {
  if (config.axes.size() != n)
    throw std::invalid_argument("ipo::Channel: " + std::to_string(config.axes.size()) +
                                " channel axes for " + std::to_string(n) + " interpolated axes");
  return config.axes;
}

}  // namespace

Channel::Channel(ChannelConfig config, Source& source, Sink* sink)
    : kin_(config.path.joints, config.axes.size(), std::move(config.forward), sink),
      // Without a sink nobody reads the joints: the interpolator then does not compute them;
      // under a kinematic the channel reads them (NC6210's jerk stencil).
      ipo_(prepared(config.path), source,
           sink != nullptr || config.path.joints ? kin_.relay() : nullptr),
      source_(source),
      sink_(sink),
      axes_(checked_axes(config, ipo_.axis_count()), config.path.start, ipo_.t_cycle()),
      exact_stop_(config.exact_stop_wait_max, ipo_.t_cycle()),
      indp_(indp_configs(config), ipo_.t_cycle(), config.path.start),
      tracking_(sync_, ipo_, axes_, indp_, kin_, after_, error_, sink,
                config.measured_value_wait_max, config.conveyor_axis),
      mapping_(kin_, tracking_, sync_, axes_, error_, ipo_.t_cycle()) {
  const double t = ipo_.t_cycle();
  ipo_.set_wait_handler(&wait_relay_);
  // Conveyor tracking on FCT_DLM channels.
  if (config.conveyor) {
    sync_.emplace(*config.conveyor, config.sync_axes, t);
    mapping_.set_shares();  // fixed by T0: set once
    tracking_.set_static_unit(config.conveyor->x_virtual);
    // The stop after an error while synchronised (tracking/sync_error.hpp).
    std::vector<AfterErrorAxis> after;
    for (std::size_t i = 0; i < config.axes.size(); ++i)
      after.push_back(after_error_axis(config.path.axes[i], config.axes[i].monitor.soft_limits));
    after_.configure(after, t);
    after_box_ = config.conveyor->workspace;
  }
}

std::string format_text(const char* format, double a, double b) {
  char buf[256];
  std::snprintf(buf, sizeof buf, format, a, b);
  return buf;
}

void raise(std::optional<RunTimeError>& error, const char* id, std::string message, const Cycle& c,
           int axis) noexcept {
  try {
    RunTimeError e;
    e.id = id;
    e.message = std::move(message);
    e.line = c.line;
    e.file = c.file;
    e.t = c.t;
    e.axis = axis;
    error = std::move(e);
  } catch (...) {
    std::abort();  // out of memory while reporting a run-time error: nothing sane is left
  }
}

bool Channel::drive_axis(std::size_t i, const Cycle& c) noexcept {
  const bool waiting = exact_stop_.waits_for(i);
  const bool active = indp_.axes().owned(i) ? !indp_.axes().in_position(i)
                                            : c.activity == Activity::motion && !waiting;
  return axes_.drive(i, c, active, waiting, exact_stop_.target(i), exact_stop_.waited(), error_);
}

Status Channel::step() noexcept {
  indp_.clear_tech();  // the technology functions of this cycle
  // After an error while synchronised the machine moves on (004 §2.3).
  if (sync_error_ && !error_) return sync_error_cycle(true);
  const std::uint64_t before = ipo_.cycle().index;
  const Status s = step_program();
  if (s != Status::error || !sync_error_begin()) return s;
  return sync_error_cycle(ipo_.cycle().index == before);
}

Status Channel::step_program() noexcept {
  if (error_) return Status::error;
  if (ended_) return *ended_;  // the player sees each cycle once
  Status ended = Status::running;
  if (!play_.step(tracking_.tracking(), port_, ended, error_)) return ended;
  // A blocked event is dispatched again each cycle; a path holding at a ChannelWait goes on in
  // this cycle once the events up to the wait's tag are done.
  if (events_.blocked() || ipo_.holding_channel()) {
    const bool holding = ipo_.holding_channel();
    const bool done = run_events(holding ? events_.wait_tag() : ipo_.cycle().event_tag);
    if (error_) return Status::error;
    if (done && holding && indp_.syn_done(events_.wait_interruptible(), axes_.size()))
      ipo_.release_wait();
  }
  tracking_.static_override();  // a synchronised static unit's path follows the belt
  Status s = ipo_.step();
  if (error_) return Status::error;  // raised by an event at a ChannelWait inside the step
  if (s == Status::finished) {
    run_events(~std::uint32_t{0});  // none left: ProgramSource ends with a ChannelWait
    if (error_) s = Status::error;
  }
  if (s == Status::finished && !indp_.axes().in_position_mask(0))
    return indp_tail();  // the program end waits for the INDP axes
  if (s != Status::running) {
    ended_ = s;
    return s;
  }
  const Cycle& c = ipo_.cycle();
  driven_ = 0;
  if (!play_.check(c, tracking_.hold_waits(), error_)) return Status::error;
  // Events riding on the blocks started in this cycle.
  if (!events_.blocked()) run_events(c.event_tag);
  if (error_) return Status::error;
  if (!tracking_.world_step(c, play_.player())) return Status::error;
  if (!mapping_.map(c)) return Status::error;
  if (!tracking_.workspace(c)) return Status::error;
  if (!exact_stop_.active() && ipo_.holding_exact_stop())
    exact_stop_.begin(c, std::span(axes_.setpoints().data(), axes_.size()), kin_.transformed());
  if (!indp_.step(c, axes_, shown_, error_)) return Status::error;
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    driven_ = i + 1;  // a monitor's alarm comes after the axis's control step
    if (!drive_axis(i, c)) return Status::error;
  }
  if (exact_stop_.active()) {
    bool release = false;
    if (!exact_stop_.check(c, axes_, release, error_)) return Status::error;
    if (release) ipo_.release_exact_stop();
  }
  if (sink_) sink_->on_cycle(cycle());  // with the INDP axes' setpoints
  return Status::running;
}

Status Channel::indp_tail() noexcept {
  const Cycle& c = indp_.tail(ipo_.cycle(), ipo_.t_cycle());
  mapping_.map(c);
  if (!indp_.step(c, axes_, shown_, error_)) return Status::error;
  for (std::size_t i = 0; i < axes_.size(); ++i)
    if (!drive_axis(i, c)) return Status::error;
  if (sink_) sink_->on_cycle(cycle());
  return Status::running;
}

}  // namespace ncsim::ipo

// channel/channel: the channel loop (see the header and docs/ipo.md "The channel loop").

#include "channel/channel.hpp"

#include <cstdlib>
#include <span>
#include <stdexcept>
#include <utility>

namespace ncsim::channel {

namespace {

ipo::Config prepared(ipo::Config config) {
  config.detail = ipo::Detail::axes;  // the axes need the point every cycle
  config.hold_exact_stop = true;      // the channel ends G60 / G360 waits on actual positions
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
    throw std::invalid_argument("channel::Channel: " + std::to_string(config.axes.size()) +
                                " channel axes for " + std::to_string(n) + " interpolated axes");
  return config.axes;
}

}  // namespace

Channel::Channel(ChannelConfig config, ipo::Source& source, ipo::Sink* sink)
    : kin_(config.path.joints, config.axes.size(), std::move(config.forward), sink),
      // Without a sink nobody reads the joints: the interpolator then does not compute them;
      // under a kinematic the channel reads them (NC6210's jerk stencil).
      ipo_(prepared(config.path), source,
           sink != nullptr || config.path.joints ? kin_.relay() : nullptr),
      sink_(sink),
      axes_(checked_axes(config, ipo_.axis_count()), config.path.start, ipo_.t_cycle()),
      exact_stop_(config.exact_stop_wait_max, ipo_.t_cycle()),
      indp_(indp_configs(config), ipo_.t_cycle(), config.path.start),
      after_(ipo_, axes_, kin_, indp_, mapping_, play_, tracking_, sync_, error_, shown_, sink),
      tracking_(sync_, ipo_, axes_, indp_, kin_, after_.axes_stop(), error_, sink,
                config.measured_value_wait_max, config.conveyor_axis),
      mapping_(kin_, tracking_, sync_, axes_, error_, ipo_.t_cycle()),
      events_(source, ipo_, axes_, indp_, tracking_, sync_, after_, error_) {
  const double t = ipo_.t_cycle();
  ipo_.standstill().set_wait_handler(&events_);
  events_.exchange_signals(config.signals);
  // Conveyor tracking on FCT_DLM channels.
  if (config.conveyor) {
    sync_.emplace(*config.conveyor, config.sync_axes, t);
    mapping_.set_shares();  // fixed by T0: set once
    tracking_.set_static_unit(config.conveyor->x_virtual);
    // The stop after an error while synchronised (tracking/sync_error.hpp).
    std::vector<tracking::AfterErrorAxis> after;
    for (std::size_t i = 0; i < config.axes.size(); ++i)
      after.push_back(
          tracking::after_error_axis(config.path.axes[i], config.axes[i].monitor.soft_limits));
    after_.configure(after, config.conveyor->workspace, t);
  }
}

void raise(std::optional<RunTimeError>& error, const char* id, std::string message,
           const ipo::Cycle& c, int axis) noexcept {
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

ipo::Status Channel::step() noexcept {
  indp_.clear_tech();                         // the technology functions of this cycle
  if (after_.active()) return after_.step();  // the machine moves on after an error (004 §2.3)
  const std::uint64_t before = ipo_.cycle().index;
  const ipo::Status s = program_cycle();
  if (s != ipo::Status::error) return s;
  // The error keeps the synchronisation (the cycle is completed), or the run ends with it.
  return after_.enter(ipo_.cycle().index != before, driven_);
}

ipo::Status Channel::program_cycle() noexcept {
  if (error_) return ipo::Status::error;
  if (ended_) return *ended_;  // the player sees each cycle once
  ipo::Status s = ipo::Status::running;
  if (!play_.step(tracking_.tracking(), port_, s, error_)) return s;  // the scenario's cycle
  if (!events_.before_path()) return ipo::Status::error;  // a blocked event, a ChannelWait's events
  tracking_.static_override();            // a synchronised static unit's path follows the belt
  s = ipo_.step();                        // the path (block starts go to the scenario)
  if (error_) return ipo::Status::error;  // raised by an event at a ChannelWait inside the step
  if (s == ipo::Status::finished && !events_.at_end()) s = ipo::Status::error;  // the events left
  if (s == ipo::Status::finished && !indp_.axes().in_position_mask(0)) return indp_tail();
  if (s != ipo::Status::running) {
    ended_ = s;
    return s;
  }
  // The path's cycle: its parts in order.
  const ipo::Cycle& c = ipo_.cycle();
  driven_ = 0;
  if (!play_.check(c, tracking_.hold_waits(), error_))
    return ipo::Status::error;                        // NC6301, an action
  if (!events_.riding(c)) return ipo::Status::error;  // the events of the blocks started in it
  if (!tracking_.world_step(c, play_.player())) return ipo::Status::error;  // the conveyor world
  if (!mapping_.map(c)) return ipo::Status::error;         // the path point -> the axes' setpoints
  if (!tracking_.workspace(c)) return ipo::Status::error;  // the conveyor workspace and its hold
  // A G60 / G360 block end reached:
  if (!exact_stop_.active() && ipo_.standstill().holding_exact_stop())
    exact_stop_.begin(c, std::span(axes_.setpoints().data(), axes_.size()), kin_.transformed());
  if (!indp_.step(c, axes_, shown_, error_)) return ipo::Status::error;  // the INDP axes' setpoints
  if (!drive_axes(c)) return ipo::Status::error;  // soft limits, position control, monitors
  bool release = false;
  // The exact stop on actual positions: released, or still waiting (P-ERR-70082, NC6101).
  if (exact_stop_.active() && !exact_stop_.check(c, axes_, release, error_))
    return ipo::Status::error;
  if (release) ipo_.standstill().release_exact_stop();
  if (sink_) sink_->on_cycle(cycle());  // with the INDP axes' setpoints
  return ipo::Status::running;
}

ipo::Status Channel::indp_tail() noexcept {
  const ipo::Cycle& c = indp_.tail(ipo_.cycle(), ipo_.t_cycle());
  mapping_.map(c);
  if (!indp_.step(c, axes_, shown_, error_)) return ipo::Status::error;
  if (!drive_axes(c)) return ipo::Status::error;
  if (sink_) sink_->on_cycle(cycle());
  return ipo::Status::running;
}

bool Channel::drive_axes(const ipo::Cycle& c) noexcept {
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    driven_ = i + 1;  // a monitor's alarm comes after the axis's control step
    const bool waiting = exact_stop_.waits_for(i);
    const bool active = indp_.axes().owned(i) ? !indp_.axes().in_position(i)
                                              : c.activity == ipo::Activity::motion && !waiting;
    if (!axes_.drive(i, c, active, waiting, exact_stop_.target(i), exact_stop_.waited(), error_))
      return false;
  }
  return true;
}

}  // namespace ncsim::channel

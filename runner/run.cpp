#include "runner/run.hpp"

#include <variant>

#include "runner/texts.hpp"

namespace ncsim::runner {

/// A Sink that passes every joint and cycle to several sinks, in order.
class Run::Fanout final : public ipo::Sink {
 public:
  explicit Fanout(std::vector<ipo::Sink*> sinks) : sinks_(std::move(sinks)) {}
  void on_joint(const ipo::Joint& j) override {
    for (ipo::Sink* s : sinks_)
      s->on_joint(j);
  }
  void on_cycle(const ipo::Cycle& c) override {
    for (ipo::Sink* s : sinks_)
      s->on_cycle(c);
  }

 private:
  std::vector<ipo::Sink*> sinks_;
};

namespace {

std::unique_ptr<program::SignalHub> own_hub(const program::SignalHub* line) {
  if (line != nullptr) return nullptr;
  return std::make_unique<program::SignalHub>(std::vector<std::uint8_t>{1});
}

}  // namespace

Run::Run(std::unique_ptr<Loaded> loaded, const RunSpec& spec, program::SignalHub* hub,
         std::uint8_t channel)
    : in_(std::move(loaded)),
      own_hub_(own_hub(hub)),
      signals_(std::make_unique<program::SignalPort>(hub != nullptr ? *hub : *own_hub_,
                                                     hub != nullptr ? channel : 1)),
      interp_(in_->file, in_->machine, in_->interp),
      // refuse: check's NC4601 before the block moves (issue 34)
      src_(interp_, in_->machine,
           program::SourceConfig{.t_cycle = in_->t_cycle, .refuse_soft_limits = true}),
      config_(channel::channel_config(in_->machine, in_->t_cycle)),
      answer_positions_(spec.answer_positions) {
  src_.exchange_signals(signals_.get());
  config_.signals = signals_.get();
  if (!spec.audit) return;
  audit_ = std::make_unique<audit::Audit>(config_.path.axes, config_.path.channel.t_cycle,
                                          config_.path.start);
  if (config_.path.joints)  // the joints are the machine axes
    audit_->set_joint_limits(config_.path.joints->joints, config_.path.start, true);
}

Run::~Run() = default;

void Run::start(std::vector<ipo::Sink*> sinks) {
  // What the channel plays of a scenario (docs/scenario.md "Wiring into the channel loop"):
  // only a scenario with events or [stop]. A V.E. write at run time must reach the barrier
  // after it: then the path stops before every V.E. read (the kernel's synchronous read);
  // without writes the answer is known.
  const std::optional<scenario::Scenario>& s = in_->scenario;
  if (s && s->needs_channel()) {
    player_ = std::make_unique<scenario::Player>(*s);
    bool writes = s->workpiece_ve();  // written when a workpiece is measured
    for (const scenario::Event& e : s->events)
      for (const scenario::Action& a : e.actions)
        writes = writes || std::holds_alternative<scenario::VeWrite>(a);
    src_.answer_barriers_from(&player_->ve(), writes);
  }
  // Without any sink the channel does not compute the joints for one: none is passed then.
  ipo::Sink* sink = audit_.get();
  if (!sinks.empty()) {
    if (audit_) sinks.insert(sinks.begin(), audit_.get());
    fanout_ = std::make_unique<Fanout>(std::move(sinks));
    sink = fanout_.get();
  }
  channel_ = std::make_unique<channel::Channel>(std::move(config_), src_, sink);
  if (answer_positions_)  // position barriers
    src_.answer_positions_from(&channel_->axes().command);
  channel_->play(player_.get());
  channel_->attach_conveyor(in_->port.get());
  if (audit_) audit_->set_setpoints(&channel_->setpoints());  // axis limits on the setpoints
  if (audit_) audit_->set_belt(&channel_->belt_share());      // the belt's share
}

ipo::Status Run::step() {
  if (own_hub_) own_hub_->begin_cycle(cycles_);
  ++cycles_;
  const ipo::Status status = channel_->step();
  if (status != ipo::Status::running) {
    if (!ended_) signals_->end(channel_->cycle().line, channel_->cycle().file);
    ended_ = true;
    return status;
  }
  if (own_hub_) own_hub_->mark_stuck();  // fails the wait in the next cycle (NC6401)
  if (audit_ && channel_->transformed()) audit_->on_joints(channel_->cycle(), channel_->joints());
  if (time_) time_->add(channel_->cycle());
  if (workpieces_)
    workpieces_->add(channel_->conveyor_sync()->phase(), in_->port->last_latch().workpiece);
  return status;
}

ipo::Status Run::run(const std::function<void(const channel::Channel&)>& on_cycle) {
  ipo::Status status;
  while ((status = step()) == ipo::Status::running)
    if (on_cycle) on_cycle(*channel_);
  return status;
}

Ending Run::ending(ipo::Status last) const {
  // A program error ends the source: the blocks before it ran, then the channel stopped. A
  // run-time error stops the channel in the cycle it is raised. A [stop] of the scenario ends
  // the run before a program error the look-ahead decoded later.
  Ending e;
  e.failed = last == ipo::Status::error || (last == ipo::Status::finished &&
                                            src_.error() != nullptr && !channel_->scenario_stop());
  if (e.failed) e.error_text = failure_text(*this);
  e.endless_from = src_.ended_endless();
  e.stop = stop_reason(e.failed, *channel_, e.endless_from.has_value());
  return e;
}

void Run::count_time(std::function<void(const audit::BlockTime&)> on_block) {
  time_.emplace(channel_->t_cycle(), std::move(on_block));
}

audit::TimeResult Run::time_result() {
  return time_->finish();
}

bool Run::tracks_conveyor() const noexcept {
  return in_->port != nullptr && channel_->conveyor_sync() != nullptr;
}

void Run::count_workpieces(std::function<void(const audit::WorkpieceCycle&)> on_row) {
  workpieces_.emplace(channel_->t_cycle(), std::move(on_row));
}

std::optional<audit::WorkpieceSummary> Run::workpiece_summary() {
  if (!workpieces_) return std::nullopt;
  return workpieces_->finish();
}

}  // namespace ncsim::runner

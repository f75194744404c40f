// channel/channel_indp: the channel's INDP axes per cycle and the scenario's axis override (see
// channel/channel.hpp and docs/ipo.md "INDP axes and technology functions").

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "channel/channel.hpp"
#include "program/program_source.hpp"

namespace ncsim::ipo {

namespace {

std::string number(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

}  // namespace

bool Channel::indp_cycle(const Cycle& c) noexcept {
  indp_.step();
  indp_stepped_ = c.index;  // --- trafo-feed: sync_error_indp_step() steps it once a cycle
  planner::AxisMask owned = indp_.owned_mask();
  // An axis the path drives: its INDP state follows the path's setpoint, so an INDP command
  // starts from where (and how fast) the axis is.
  for (std::size_t i = 0; i < axes_.size(); ++i)
    if (((owned >> i) & 1u) == 0) indp_.follow(i, axes_.setpoints()[i]);
  if (owned == 0) {
    shown_ = nullptr;
    return true;
  }
  // The path programs an axis the INDP layer owns: the axis goes back to the path when its
  // INDP motion is done and the block starts where that motion left it (the interpreter's
  // position is the INDP target); P-CHAN-00451's implicit synchronisation (the path waiting
  // for a running INDP_ASYN motion) is not done: NC6103 (docs/ipo.md).
  if (c.activity == Activity::motion && c.programmed != nullptr) {
    const planner::Move& m = *c.programmed;
    for (std::size_t i = 0; i < axes_.size(); ++i) {
      if (((owned >> i) & 1u) == 0) continue;
      const bool moved =
          m.end[i] != m.start[i] || (m.arc && (m.arc->axis_1 == i || m.arc->axis_2 == i));
      if (!moved) continue;
      const double p = indp_.setpoint(i).p;
      if (!indp_.in_position(i) || std::fabs(m.start[i] - p) > 1e-9 * std::max(1.0, std::fabs(p))) {
        stop(kIndpPathId,
             "not supported: axis " + axes_.config(i).name +
                 " programmed as a path axis while its INDP motion " +
                 (indp_.in_position(i) ? "left it at " + number(p) + " (the block starts at " +
                                             number(m.start[i]) + ")"
                                       : "runs (to " + number(indp_.target(i)) + ")") +
                 "; program #WAIT INDP before (P-CHAN-00451 implicit synchronisation)",
             c, static_cast<int>(i));
        return false;
      }
      indp_.release(i);
      indp_.follow(i, axes_.setpoints()[i]);
      owned &= ~(planner::AxisMask{1} << i);
    }
  }
  patched_ = c;
  patched_.independent = owned;
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    if (((owned >> i) & 1u) == 0) continue;
    const axes::Setpoint& sp = indp_.setpoint(i);
    axes_.setpoints()[i] = sp;
    patched_.x[i] = sp.p;
    patched_.v[i] = sp.v;
    patched_.a[i] = sp.a;
    patched_.j[i] = sp.j;
  }
  shown_ = &patched_;
  return true;
}

std::optional<std::pair<const char*, std::string>> Channel::indp_override(
    const scenario::AxisOverride& o) noexcept {
  try {
    std::size_t i = 0;
    while (i < axes_.size() && axes_.config(i).name != o.axis)
      ++i;
    if (i == axes_.size())
      return std::pair{kIndpOverrideId,
                       "scenario axis override of " + o.axis +
                           ": not an axis of the channel (spindles, the conveyor and encoder axes "
                           "move no INDP motion)"};
    // 002_* 2.2: ignored_braking_phase / rejected_stopping keep the value for later.
    if (indp_.set_override(i, o.fraction) == axes::Result::error_invalid_input)
      return std::pair{kIndpOverrideId, "scenario axis override of " + o.axis + " = " +
                                            number(o.fraction * 100.0) +
                                            " % outside 0 .. 100 % (002_* 2.2)"};
    return std::nullopt;
  } catch (...) {
    std::abort();  // out of memory while reporting a run-time error
  }
}

Channel::EventOutcome Channel::indp_command(const interp::AxisCommand& c,
                                            const ChannelEvent& e) noexcept {
  std::size_t i = 0;
  while (i < axes_.size() && axes_.config(i).indp.machine_index != c.axis)
    ++i;
  if (i == axes_.size())
    return event_error(kNotSupportedId,
                       "not supported: INDP motion of a spindle, the conveyor or an encoder axis "
                       "(only interpolated axes move independently)",
                       e);
  // isg-language.md 6.1: "By default no offsets are applied": POS is the axis value (MCS) under
  // a #CS too; under #SYNC (PCS1) or #TRAFO ON the target would need the moving frame or the
  // kinematics.
  // --- trafo-feed: while synchronised an axis the belt does not move (its share of T0's X is
  // 0: Z, C) has PCS1 = MCS up to T0's constant offset: POS is its MCS value as outside #SYNC
  // (docs/conveyor.md "With INDP axes"). An axis the belt moves would need the moving frame.
  const bool belt_moves =
      c.frame.space == interp::Space::pcs1 &&
      (!sync_ || (sync_->xyz(i) >= 0 && sync_->xyz(i) < 3 &&
                  std::fabs(sync_->frame().direction()[sync_->xyz(i)]) >= 1e-12));
  if (belt_moves || c.frame.kinematics)
    return event_error(kNotSupportedId,
                       "not supported: INDP motion of axis " + axes_.config(i).name +
                           (c.frame.kinematics ? " under #TRAFO ON" : " while synchronised (PCS1)"),
                       e);
  IndpMove m;
  m.target = c.target;
  m.rapid = c.rapid;
  m.feed = c.feed;
  m.time = c.time;
  // INTERRUPTIBLE belongs to INDP_SYN motions after #SYNC OUT (TF5264 examples); with
  // INDP_ASYN it is ignored (docs/ipo.md).
  m.interruptible = c.interruptible && c.kind == interp::IndpKind::syn;
  if (const auto err = indp_.command(i, m)) return event_error(err->id.c_str(), err->message, e);
  if (c.kind == interp::IndpKind::syn) syn_ |= planner::AxisMask{1} << i;
  return EventOutcome::done;
}

Channel::EventOutcome Channel::indp_wait(const interp::WaitIndp& w, const ChannelEvent&) noexcept {
  // #WAIT INDP [axes] / ALL: "waits until axis Z's command value reaches its target"
  // (isg-language.md 6.1): blocking until then, the path holding at the wait.
  planner::AxisMask mask = 0;
  for (std::size_t i = 0; i < axes_.size(); ++i)
    if (w.axes == 0 || ((w.axes >> axes_.config(i).indp.machine_index) & 1u) != 0)
      mask |= planner::AxisMask{1} << i;
  if (mask == 0) return EventOutcome::done;  // none of the named axes is a channel axis
  return indp_.in_position_mask(mask) ? EventOutcome::done : EventOutcome::blocking;
}

Channel::EventOutcome Channel::indp_tech(const interp::Tech& t, const ChannelEvent& e) noexcept {
  if (t.sync == machines::TechSync::none) return EventOutcome::done;  // NO_SYNCH: no output
  try {
    tech_.push_back(TechOutput{static_cast<double>(ipo_.cycle().index) * ipo_.t_cycle(), e.line,
                               e.file, t.kind, t.value, t.extra});
  } catch (...) {
    std::abort();  // out of memory: bounded by the events of one cycle (kMaxPendingEvents)
  }
  return EventOutcome::done;
}

bool Channel::indp_syn_done() noexcept {
  planner::AxisMask wait = syn_;
  // --- sync-feed: before the next synchronisation the program goes on while INTERRUPTIBLE
  // INDP_SYN motions run; the catch-up takes them over (docs/conveyor.md S-4).
  if (wait_interruptible_)
    for (std::size_t i = 0; i < axes_.size(); ++i)
      if (indp_.interruptible(i)) wait &= ~(planner::AxisMask{1} << i);
  if (wait != 0 && !indp_.in_position_mask(wait)) return false;
  syn_ = 0;
  return true;
}

Status Channel::indp_tail() noexcept {
  // The path stands at its end; the cycles go on (Activity::channel, counted as waiting by
  // `time`) until every INDP axis is in position, so `run` and `time` cover the whole motion.
  if (!in_tail_) {
    tail_ = ipo_.cycle();
    in_tail_ = true;
    tail_.activity = Activity::channel;
    tail_.programmed = nullptr;
    tail_.path.v = tail_.path.a = tail_.path.j = 0.0;
    tail_.distance = 0.0;
    tail_.lost = 0.0;
    tail_.v = AxisVec{};
    tail_.a = AxisVec{};
    tail_.j = AxisVec{};
  }
  ++tail_.index;
  tail_.t = static_cast<double>(tail_.index) * ipo_.t_cycle();
  map_to_axes(tail_);
  if (!indp_cycle(tail_)) return Status::error;
  for (std::size_t i = 0; i < axes_.size(); ++i)
    if (!drive_axis(i, tail_)) return Status::error;
  if (sink_) sink_->on_cycle(cycle());
  return Status::running;
}

}  // namespace ncsim::ipo

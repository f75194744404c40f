// channel/indp_stage: the channel's INDP axes and technology outputs (see the header and
// docs/ipo.md "INDP axes and technology functions").

#include "channel/indp_stage.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "core/number_text.hpp"
#include "core/tolerance.hpp"
#include "program/program_source.hpp"

namespace ncsim::channel {

IndpStage::IndpStage(std::vector<IndpAxisConfig> axes, double t_cycle,
                     const planner::AxisVec& start)
    : indp_(std::move(axes), t_cycle, start) {}

void IndpStage::step_once(const ipo::Cycle& c) noexcept {
  if (stepped_ == c.index) return;  // the error's own cycle may have stepped them already
  indp_.step();
  stepped_ = c.index;
}

bool IndpStage::step(const ipo::Cycle& c, AxisStage& axes, const ipo::Cycle*& shown,
                     std::optional<RunTimeError>& error) noexcept {
  indp_.step();
  stepped_ = c.index;
  planner::AxisMask owned = indp_.owned_mask();
  // An axis the path drives: its INDP state follows the path's setpoint, so an INDP command
  // starts from where (and how fast) the axis is.
  for (std::size_t i = 0; i < axes.size(); ++i)
    if (((owned >> i) & 1u) == 0) indp_.follow(i, axes.setpoints()[i]);
  if (owned == 0) {
    shown = nullptr;
    return true;
  }
  // The path programs an axis the INDP layer owns: the axis goes back to the path when its
  // INDP motion is done and the block starts where that motion left it (the interpreter's
  // position is the INDP target); P-CHAN-00451's implicit synchronisation (the path waiting
  // for a running INDP_ASYN motion) is not done: NC6103 (docs/ipo.md).
  if (c.activity == ipo::Activity::motion && c.programmed != nullptr) {
    const planner::Move& m = *c.programmed;
    for (std::size_t i = 0; i < axes.size(); ++i) {
      if (((owned >> i) & 1u) == 0) continue;
      const bool moved =
          m.end[i] != m.start[i] || (m.arc && (m.arc->axis_1 == i || m.arc->axis_2 == i));
      if (!moved) continue;
      const double p = indp_.setpoint(i).p;
      if (!indp_.in_position(i) ||
          std::fabs(m.start[i] - p) > kRelTol * std::max(1.0, std::fabs(p))) {
        raise(
            error, kIndpPathId,
            "not supported: axis " + axes.config(i).name +
                " programmed as a path axis while its INDP motion " +
                (indp_.in_position(i) ? "left it at " + core::human(p) + " (the block starts at " +
                                            core::human(m.start[i]) + ")"
                                      : "runs (to " + core::human(indp_.target(i)) + ")") +
                "; program #WAIT INDP before (P-CHAN-00451 implicit synchronisation)",
            c, static_cast<int>(i));
        return false;
      }
      indp_.release(i);
      indp_.follow(i, axes.setpoints()[i]);
      owned &= ~(planner::AxisMask{1} << i);
    }
  }
  patched_ = c;
  patched_.independent = owned;
  for (std::size_t i = 0; i < axes.size(); ++i) {
    if (((owned >> i) & 1u) == 0) continue;
    const axes::Setpoint& sp = indp_.setpoint(i);
    axes.setpoints()[i] = sp;
    patched_.x[i] = sp.p;
    patched_.v[i] = sp.v;
    patched_.a[i] = sp.a;
    patched_.j[i] = sp.j;
  }
  shown = &patched_;
  return true;
}

std::optional<std::pair<const char*, std::string>> IndpStage::set_override(
    const scenario::AxisOverride& o, const AxisStage& axes) noexcept {
  try {
    std::size_t i = 0;
    while (i < axes.size() && axes.config(i).name != o.axis)
      ++i;
    if (i == axes.size())
      return std::pair{kIndpOverrideId,
                       "scenario axis override of " + o.axis +
                           ": not an axis of the channel (spindles, the conveyor and encoder axes "
                           "move no INDP motion)"};
    // 002_* 2.2: ignored_braking_phase / rejected_stopping keep the value for later.
    if (indp_.set_override(i, o.fraction) == axes::Result::error_invalid_input)
      return std::pair{kIndpOverrideId, "scenario axis override of " + o.axis + " = " +
                                            core::human(o.fraction * 100.0) +
                                            " % outside 0 .. 100 % (002_* 2.2)"};
    return std::nullopt;
  } catch (...) {
    std::abort();  // out of memory while reporting a run-time error
  }
}

EventOutcome IndpStage::command(const interp::AxisCommand& c, const AxisStage& axes,
                                const tracking::ConveyorSync* sync,
                                const EventContext& ctx) noexcept {
  const std::size_t i = axes.find(c.axis);
  if (i == axes.size())
    return ctx.fail(program::kNotSupportedId,
                    "not supported: INDP motion of a spindle, the conveyor or an encoder axis "
                    "(only interpolated axes move independently)");
  // isg-language.md 6.1: "By default no offsets are applied": POS is the axis value (MCS) under
  // a #CS too; under #SYNC (PCS1) or #TRAFO ON the target would need the moving frame or the
  // kinematics.
  // while synchronised an axis the belt does not move (its share of T0's X is
  // 0: Z, C) has PCS1 = MCS up to T0's constant offset: POS is its MCS value as outside #SYNC
  // (docs/conveyor.md "With INDP axes"). An axis the belt moves would need the moving frame.
  const bool belt_moves = c.frame.space == interp::Space::pcs1 &&
                          (!sync || (sync->xyz(i) >= 0 && sync->xyz(i) < 3 &&
                                     std::fabs(sync->frame().direction()[sync->xyz(i)]) >= kTiny));
  if (belt_moves || c.frame.kinematics)
    return ctx.fail(program::kNotSupportedId,
                    "not supported: INDP motion of axis " + axes.config(i).name +
                        (c.frame.kinematics ? " under #TRAFO ON" : " while synchronised (PCS1)"));
  IndpMove m;
  m.target = c.target;
  m.rapid = c.rapid;
  m.feed = c.feed;
  m.time = c.time;
  // INTERRUPTIBLE belongs to INDP_SYN motions after #SYNC OUT (TF5264 examples); with
  // INDP_ASYN it is ignored (docs/ipo.md).
  m.interruptible = c.interruptible && c.kind == interp::IndpKind::syn;
  if (const auto err = indp_.command(i, m)) return ctx.fail(err->id.c_str(), err->message);
  if (c.kind == interp::IndpKind::syn) syn_ |= planner::AxisMask{1} << i;
  return EventOutcome::done;
}

EventOutcome IndpStage::wait(const interp::WaitIndp& w, const AxisStage& axes) const noexcept {
  // #WAIT INDP [axes] / ALL: "waits until axis Z's command value reaches its target"
  // (isg-language.md 6.1): blocking until then, the path holding at the wait.
  planner::AxisMask mask = 0;
  for (std::size_t i = 0; i < axes.size(); ++i)
    if (w.axes == 0 || ((w.axes >> axes.config(i).indp.machine_index) & 1u) != 0)
      mask |= planner::AxisMask{1} << i;
  if (mask == 0) return EventOutcome::done;  // none of the named axes is a channel axis
  return indp_.in_position_mask(mask) ? EventOutcome::done : EventOutcome::blocking;
}

EventOutcome IndpStage::tech(const interp::Tech& t, const EventContext& ctx) noexcept {
  if (t.sync == machines::TechSync::none) return EventOutcome::done;  // NO_SYNCH: no output
  try {
    const program::ChannelEvent& e = ctx.event();
    tech_.push_back(TechOutput{ctx.t(), e.line, e.file, t.kind, t.value, t.extra});
  } catch (...) {
    std::abort();  // out of memory: bounded by the events of one cycle (kMaxPendingEvents)
  }
  return EventOutcome::done;
}

bool IndpStage::syn_done(bool interruptible, std::size_t n) noexcept {
  planner::AxisMask wait = syn_;
  // Before the next synchronisation the program goes on while INTERRUPTIBLE INDP_SYN motions
  // run; the catch-up takes them over (docs/conveyor.md S-4).
  if (interruptible)
    for (std::size_t i = 0; i < n; ++i)
      if (indp_.interruptible(i)) wait &= ~(planner::AxisMask{1} << i);
  if (wait != 0 && !indp_.in_position_mask(wait)) return false;
  syn_ = 0;
  return true;
}

// The on-the-fly change (004 l.277-279, docs/conveyor.md S-4).
bool IndpStage::hand_over(std::size_t n) noexcept {
  bool ready = true;
  for (std::size_t i = 0; i < n; ++i) {
    if (!indp_.owned(i)) continue;
    if (indp_.in_position(i)) {
      indp_.release(i);  // its setpoint is where the INDP motion left it
    } else if (!indp_.hand_over(i)) {
      ready = false;  // not INTERRUPTIBLE (or INDP_ASYN): the motion first ends in position
    }
  }
  return ready;
}

const ipo::Cycle& IndpStage::tail(const ipo::Cycle& last, double t_cycle) noexcept {
  // The path stands at its end; the cycles go on (Activity::channel, counted as waiting by
  // `time`) until every INDP axis is in position, so `run` and `time` cover the whole motion.
  if (!in_tail_) {
    tail_ = last;
    in_tail_ = true;
    tail_.activity = ipo::Activity::channel;
    tail_.programmed = nullptr;
    tail_.path.v = tail_.path.a = tail_.path.j = 0.0;
    tail_.distance = 0.0;
    tail_.lost = 0.0;
    tail_.v = planner::AxisVec{};
    tail_.a = planner::AxisVec{};
    tail_.j = planner::AxisVec{};
  }
  ++tail_.index;
  tail_.t = static_cast<double>(tail_.index) * t_cycle;
  return tail_;
}

}  // namespace ncsim::channel

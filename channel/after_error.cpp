// channel/after_error: the after-error state machine (see the header; seed 004 §2.3 l.492-498;
// docs/conveyor.md "Errors while synchronised").
//
// Flow: the program's cycle raised a run-time error in the tracking phase, synchronised: keep()
// holds it back (held_), aborts the program (its blocks only brake), gives the path the feed hold
// (a jerk-limited stop on its contour in PCS1) and the cycle is completed here: the belt's Port
// is stepped, the setpoints mapped with the PCS1 offset, the axes driven (no monitor: the channel
// is in its error state) and the cycle shown. Every later cycle does the same with a fresh
// interpolator cycle (or, once the interpolator has ended, a copy of its last one at rest) until
// the stop says the axes (the TCP) must brake before a limit; its braking ramps then replace the
// setpoints, and when everything is at rest (or the belt and the path stand) the run ends with
// the original error: its id, line and time.

#include "channel/after_error.hpp"

#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>

#include "core/number_text.hpp"

namespace ncsim::channel {

namespace {

const char* end_text(tracking::AfterErrorEnd why) noexcept {
  switch (why) {
    case tracking::AfterErrorEnd::soft_limit:
      return "braked before its soft limit";
    case tracking::AfterErrorEnd::velocity:
      return "braked: following the belt would exceed its maximum velocity";
    case tracking::AfterErrorEnd::belt_stop:
      return "stood with the belt";
    case tracking::AfterErrorEnd::time_limit:
      return "braked after ncsim's longest following";
  }
  return "";
}

}  // namespace

AfterErrorStop::AfterErrorStop(ipo::PathInterpolator& ipo, AxisStage& axes, KinematicStage& kin,
                               IndpStage& indp, AxisMapping& mapping, ScenarioPlay& play,
                               const ConveyorTracking& tracking,
                               std::optional<tracking::ConveyorSync>& sync,
                               std::optional<RunTimeError>& error, const ipo::Cycle*& shown,
                               ipo::Sink* sink) noexcept
    : ipo_(ipo),
      axes_(axes),
      kin_(kin),
      indp_(indp),
      mapping_(mapping),
      play_(play),
      tracking_(tracking),
      sync_(sync),
      error_(error),
      shown_(shown),
      sink_(sink) {}

void AfterErrorStop::configure(std::span<const tracking::AfterErrorAxis> axes,
                               const machines::Workspace& box, double t_cycle) noexcept {
  axes_stop_.configure(axes, t_cycle);
  box_ = box;
}

ipo::Status AfterErrorStop::enter(bool own_cycle, std::size_t driven) noexcept {
  if (!keep()) return ipo::Status::error;
  return cycle(!own_cycle, own_cycle ? driven : 0);
}

bool AfterErrorStop::keep() noexcept {
  if (!error_ || state_ != State::idle || !sync_ || !axes_stop_.usable()) return false;
  if (sync_->phase() != tracking::SyncPhase::tracking || !sync_->synchronised()) return false;
  // Not built (docs/conveyor.md): a static unit (no real X follows the belt).
  if (tracking_.static_unit()) return false;
  if (!tracking::SyncErrorStop::keeps_synchronisation(error_->id)) return false;
  if (!begin_indp()) return false;  // the INDP axes brake on their own ramps
  case_ = Case::axes;
  if (kin_.transformed() && !begin_tcp()) return false;  // under #TRAFO ON the TCP's stop
  held_ = std::move(error_);
  play_.abort_program();  // its blocks only brake now
  error_.reset();
  axes_stop_.begin();
  path_ended_ = false;
  ipo_.path_override().set_feed_hold(true);  // the path velocity in PCS1 goes to 0 (l.494)
  ipo_.path_override().set_velocity_cap(tracking::WorkspaceHold::kNone);
  state_ = State::following;
  return true;
}

ipo::Status AfterErrorStop::cycle(bool fresh, std::size_t first) noexcept {
  const ipo::Cycle& c = next_cycle(fresh);
  shown_ = &cycle_;
  // The belt's world goes on (its errors are not raised again: the channel is in error).
  (void)sync_->step(c.t);
  bool stood = false;
  if (!stop_cycle(c, stood)) {
    passed_ = "; the TCP would have left the kinematic's reach: the run ended there";
    finish(c.t - ipo_.t_cycle());
    return ipo::Status::error;
  }
  if (beyond_soft_limit(c, fresh, first)) return ipo::Status::error;
  for (std::size_t i = first; i < axes_.size(); ++i)
    axes_.follow(i);
  if (sink_) sink_->on_cycle(cycle_);
  if (stood) finish(c.t);             // the next step() ends the run with the original error
  if (error_) state_ = State::ended;  // or with one a part raised after it
  return ipo::Status::running;
}

const ipo::Cycle& AfterErrorStop::next_cycle(bool fresh) noexcept {
  const double t_cycle = ipo_.t_cycle();
  if (fresh && !path_ended_) {
    if (ipo_.step() != ipo::Status::running) {  // the path ended (or its source failed) meanwhile
      path_ended_ = true;
      cycle_ = ipo_.cycle();
      cycle_.index -= 1;  // advanced below
    }
  }
  if (!path_ended_) {
    cycle_ = ipo_.cycle();
  } else if (fresh) {  // the path stands at its last point: the cycles go on at rest
    cycle_.index += 1;
    cycle_.t = static_cast<double>(cycle_.index) * t_cycle;
    cycle_.path.v = cycle_.path.a = cycle_.path.j = 0.0;
    cycle_.v = cycle_.a = cycle_.j = planner::AxisVec{};
    cycle_.distance = 0.0;
    cycle_.held = true;
    cycle_.factor = 0.0;
    cycle_.lost = t_cycle;
  }
  return cycle_;
}

bool AfterErrorStop::stop_cycle(const ipo::Cycle& c, bool& end) noexcept {
  const std::size_t n = axes_.size();
  const bool tcp = case_ == Case::tcp;
  // The axes following the belt (under #TRAFO ON the TCP, and its joints where the transform
  // maps it).
  const bool mapped = mapping_.map(c);
  if (tcp && !mapped) error_.reset();  // NC3201 is not raised after the error: the run ends below
  step_indp(c);
  tracking::SyncErrorStop& stop = tcp ? tcp_stop_ : axes_stop_;
  if (state_ == State::braking) {
    stop.step(std::span(tcp ? kin_.tcp().data() : axes_.setpoints().data(), n));
    end = stop.stood() && indp_stood();
    if (tcp) return kin_.map_tcp(axes_);  // the joints of the braking TCP
    apply_indp();
    return true;
  }
  if (tcp && !mapped) return false;
  const std::array<axes::Setpoint, planner::kMaxAxes> x = seen();
  const std::span<const axes::Setpoint> s(x.data(), n);
  tracking::AfterErrorEnd why = tracking::AfterErrorEnd::soft_limit;
  int axis = -1;
  const bool path_stands = c.path.v == 0.0 && c.path.a == 0.0;
  const bool belt_stands =
      std::fabs(sync_->belt_velocity()) <= tracking::SyncErrorStop::kStandstill;
  if (path_stands && belt_stands) {
    stop.start_stopping(s, tracking::AfterErrorEnd::belt_stop, -1);
    end = indp_stood();
  } else if (stop.must_stop(s, why, axis)) {
    stop.start_stopping(s, why, axis);  // this cycle as computed, braking from the next
  } else if (tcp && axes_stop_.must_stop(
                        std::span<const axes::Setpoint>(axes_.setpoints().data(), n), why, axis)) {
    joint_ = axis;  // a joint would pass its soft limit or exceed its V: the TCP brakes
    joint_why_ = why;
    stop.start_stopping(s, why, -1);
  }
  if (stop.stopping()) state_ = State::braking;
  stop.follow_cycle();
  return true;
}

std::array<axes::Setpoint, planner::kMaxAxes> AfterErrorStop::seen() const noexcept {
  std::array<axes::Setpoint, planner::kMaxAxes> out{};
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    out[i] = case_ == Case::tcp ? kin_.tcp()[i] : axes_.setpoints()[i];
    // the INDP axes enter at rest: not the stop's to brake
    if ((indp_mask_ >> i) & 1u) out[i] = axes::Setpoint{axes_.setpoints()[i].p, 0.0, 0.0, 0.0};
  }
  return out;
}

bool AfterErrorStop::beyond_soft_limit(const ipo::Cycle& c, bool fresh,
                                       std::size_t first) noexcept {
  // No axis receives a set position beyond its soft limit (as AxisStage::drive). The stop is
  // planned not to get there; a machine already at its limit when the error came cannot follow
  // at all.
  for (std::size_t i = first; i < axes_.size(); ++i) {
    const auto alarm = axes::check_soft_limits(axes_.config(i).monitor.soft_limits,
                                               axes_.setpoints()[i].p, static_cast<int>(i), c.t);
    if (!alarm) continue;
    if (!fresh) {  // the error's own cycle: it ends the run as every error does (no note)
      error_ = std::move(held_);
      held_.reset();
      state_ = State::dropped;
      return true;
    }
    try {
      passed_ = "; axis " + axes_.config(i).name + " would have passed its soft limit " +
                core::human(alarm->limit) + " mm at t=" + core::human(c.t) +
                " s: the run ended there";
    } catch (...) {
      std::abort();
    }
    finish(c.t - ipo_.t_cycle());
    return true;
  }
  return false;
}

void AfterErrorStop::finish(double t) noexcept {
  end_t_ = t;
  error_ = held_;
  state_ = State::ended;
}

std::string AfterErrorStop::note() const {
  if (!held_) return {};
  return case_ == Case::tcp ? tcp_note() : axes_note();
}

std::string AfterErrorStop::axes_note() const {
  std::string axis;
  std::string limit;
  if (axes_stop_.axis() >= 0) {
    const auto i = static_cast<std::size_t>(axes_stop_.axis());
    axis = " axis " + axes_.config(i).name;
    const tracking::AfterErrorAxis& l = axes_stop_.limits(i);
    if (axes_stop_.why() == tracking::AfterErrorEnd::soft_limit) {
      const double p = axes_.setpoints()[i].p;
      const bool up = l.soft.max_enabled &&
                      (!l.soft.min_enabled ||
                       std::fabs(l.soft.max_position - p) < std::fabs(p - l.soft.min_position));
      limit = " " + core::human(up ? l.soft.max_position : l.soft.min_position) + " mm (" +
              (up ? "P-AXIS-00178" : "P-AXIS-00177") + "), standing at " +
              core::human(axes_.setpoints()[i].p) + " mm";
    }
  }
  return "synchronisation kept after " + held_->id +
         " (004 §2.3): the path braked to 0 in PCS1, the machine followed the belt for " +
         core::human(axes_stop_.followed()) + " s;" + axis + " " + end_text(axes_stop_.why()) +
         limit + "; it stood at t=" + core::human(end_t_) + " s" + indp_note() + passed_;
}

}  // namespace ncsim::channel

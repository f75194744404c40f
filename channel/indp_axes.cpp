// channel/indp_axes: independent axes, one PTP profile each (see the header and docs/ipo.md
// "INDP axes and technology functions").

#include "channel/indp_axes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "axes/axis_config.hpp"
#include "core/number_text.hpp"
#include "core/tolerance.hpp"

namespace ncsim::channel {

namespace {
/// [mm/s | deg/s] the least V of a TIME= move: a level of 0 still gives a positive V.
constexpr double kVelocityFloor = 1e-12;
}  // namespace

IndpAxisConfig indp_axis_config(const machines::AxisParams& axis) {
  const machines::Dynamics& d = axis.dynamics;
  IndpAxisConfig c;
  c.name = axis.name;
  // G01: the limits the path and the audit use (program::machine_config).
  c.feed.v_max = d.v_max;                          // P-AXIS-00212
  c.feed.a_max = std::min(d.acc_feed, d.acc_max);  // P-AXIS-00001 capped by P-AXIS-00008
  c.feed.d_max = std::min(d.dec_feed, d.acc_max);  // P-AXIS-00002 capped by P-AXIS-00008
  c.feed.j_max = d.jerk_feed();                    // P-AXIS-00195..00198
  // G00: P-AXIS-00209 at the smaller of the G01 and the G00 slope (P-AXIS-00004, P-AXIS-00200).
  const double a_rapid = std::min(d.acc_rapid, d.acc_max);
  c.rapid.v_max = std::min(d.v_rapid, d.v_max);
  c.rapid.a_max = std::min(c.feed.a_max, a_rapid);
  c.rapid.d_max = std::min(c.feed.d_max, a_rapid);
  c.rapid.j_max = d.ramp_rapid > 0.0 ? std::min(c.feed.j_max, d.jerk_rapid()) : c.feed.j_max;
  const axes::GeneratorConfig g = axes::make_generator_config(axis);
  c.increment = g.increment;
  c.rule = g.profile_rule;  // NCSIM-AXIS-030
  c.override_type = g.override_type;
  c.limits = axes::make_monitor_params(axis).soft_limits;  // P-AXIS-00177 / 00178
  return c;
}

namespace {

std::string fmt(double x) {
  return core::number_text(x);
}

}  // namespace

IndpAxes::IndpAxes(std::vector<IndpAxisConfig> axes, double t_cycle, const planner::AxisVec& start)
    : t_cycle_(t_cycle) {
  if (!(std::isfinite(t_cycle) && t_cycle > 0.0))
    throw std::invalid_argument("channel::IndpAxes: t_cycle must be > 0 s, got " + fmt(t_cycle));
  if (axes.size() > planner::kMaxAxes)
    throw std::invalid_argument("channel::IndpAxes: " + std::to_string(axes.size()) + " axes");
  axes_.reserve(axes.size());
  for (std::size_t i = 0; i < axes.size(); ++i) {
    Axis a;
    a.config = std::move(axes[i]);
    a.sp = axes::Setpoint{start[i], 0.0, 0.0, 0.0};
    a.target = start[i];
    a.profile = axes::Profile::at_rest(start[i]);
    axes_.push_back(std::move(a));
  }
}

axes::MotionState IndpAxes::state(const Axis& a) const noexcept {
  return axes::MotionState{a.sp.p, a.sp.v, a.sp.a};
}

void IndpAxes::take(Axis& a, const axes::Profile& p) noexcept {
  a.profile = p;
  a.k = 0;
  a.t = 0.0;
  a.mode = Mode::moving;
}

axes::Result IndpAxes::replan(Axis& a) noexcept {
  axes::Profile p;
  if (a.override_ == 0.0) {
    // 002_* 2.2: stop is override 0; the target is kept, the axis holds.
    const axes::Result r = axes::plan_stop(state(a), a.dynamics, p);
    if (r != axes::Result::ok) return r;
    a.profile = p;
    a.k = 0;
    a.t = 0.0;
    a.mode = Mode::held;
    return r;
  }
  const double v_ref =
      a.config.override_type == axes::OverrideType::reduced_iterated ? a.v_level : a.dynamics.v_max;
  axes::Dynamics d = a.dynamics;
  d.v_max = v_ref * a.override_;
  const axes::Result r =
      axes::plan_position(state(a), axes::PositionTarget{a.target, 0.0}, d, p, a.config.rule);
  if (r == axes::Result::ok) take(a, p);
  return r;
}

std::optional<IndpError> IndpAxes::command(std::size_t i, const IndpMove& move) noexcept {
  Axis& a = axes_[i];
  const std::string_view name = a.config.name;
  try {
    if (const auto alarm =
            axes::check_soft_limits(a.config.limits, move.target, static_cast<int>(i), 0.0)) {
      const bool low = alarm->kind == axes::AlarmKind::soft_limit_min;
      return IndpError{std::string(alarm->id),
                       "axis " + std::string(name) + ": INDP target " + fmt(move.target) +
                           (low ? " below the minimum soft position limit " + fmt(alarm->limit) +
                                      " (P-AXIS-00177)"
                                : " above the maximum soft position limit " + fmt(alarm->limit) +
                                      " (P-AXIS-00178)")};
    }
    a.owned = true;
    a.interruptible = false;
    if (a.mode == Mode::idle && std::abs(move.target - a.sp.p) < a.config.increment) {
      a.target = a.sp.p;  // 002_* 2.1: shorter than one increment: no start
      return std::nullopt;
    }
    axes::Dynamics d = move.rapid ? a.config.rapid : a.config.feed;
    if (!move.rapid && move.feed && !move.time) {
      if (*move.feed > d.v_max) ++capped_;  // FEED above P-AXIS-00212: capped like the path's F
      d.v_max = std::min(*move.feed, d.v_max);
    }
    const axes::MotionState s = state(a);
    const axes::PositionTarget target{move.target, 0.0};
    axes::Profile full;
    axes::Result r = axes::plan_position(s, target, d, full, a.config.rule);
    if (r == axes::Result::ok && move.time) {
      if (*move.time > full.duration()) {
        axes::Profile timed;
        // A target at rest takes every TIME from the fastest profile on (at the latest by the
        // rest family: docs/axes-profile.md, "Prescribed durations"); should none take it
        // (NC5015), the fastest profile runs instead, counted like a cap.
        if (axes::plan_position_of_duration(s, target, d, *move.time, timed) == axes::Result::ok)
          full = timed;
        else
          ++capped_;
      } else if (*move.time < full.duration()) {
        ++capped_;  // TIME shorter than the fastest profile: the fastest profile runs
      }
    }
    if (r != axes::Result::ok)
      return IndpError{kIndpPlanId, "axis " + std::string(name) + ": INDP motion to " +
                                        fmt(move.target) +
                                        " not planned: " + std::string(axes::describe(r)) + " [" +
                                        std::string(axes::diagnostic_id(r)) + "]"};
    a.target = move.target;
    a.dynamics = d;
    a.v_level = full.v_level();
    if (move.time) a.dynamics.v_max = std::max(a.v_level, kVelocityFloor);  // the level TIME= chose
    a.interruptible = move.interruptible;
    if (a.override_ == 1.0) {
      take(a, full);
      return std::nullopt;
    }
    r = replan(a);
    if (r != axes::Result::ok)
      return IndpError{kIndpPlanId, "axis " + std::string(name) + ": INDP motion to " +
                                        fmt(move.target) + " not planned at override " +
                                        fmt(a.override_) + ": " + std::string(axes::describe(r))};
    return std::nullopt;
  } catch (...) {
    std::abort();  // out of memory while building a message: nothing sane is left
  }
}

axes::Result IndpAxes::set_override(std::size_t i, double fraction) noexcept {
  if (!(fraction >= 0.0 && fraction <= 1.0)) return axes::Result::error_invalid_input;
  Axis& a = axes_[i];
  const double previous = a.override_;
  a.override_ = fraction;
  switch (a.mode) {
    case Mode::idle:
      return axes::Result::ok;  // applies from the next command
    case Mode::stopping:
      return axes::Result::rejected_stopping;
    case Mode::moving:
      // 002_* 2.2: "nur aktiviert, wenn kein Stop vorliegt und wenn die Bremsphase noch nicht
      // erreicht worden ist"; the value is kept for later.
      if (a.t >= a.profile.t_brake()) return axes::Result::ignored_braking_phase;
      break;
    case Mode::held:
      break;
  }
  if (fraction == previous) return axes::Result::ok;
  const axes::Result r = replan(a);
  if (r != axes::Result::ok) a.override_ = previous;
  return r;
}

bool IndpAxes::interruptible(std::size_t i) const noexcept {
  const Axis& a = axes_[i];
  return a.interruptible && a.mode != Mode::idle && a.mode != Mode::stopping;
}

bool IndpAxes::interrupt(std::size_t i) noexcept {
  if (!interruptible(i)) return false;
  Axis& a = axes_[i];
  a.interruptible = false;
  axes::Profile p;
  if (axes::plan_stop(state(a), a.dynamics, p) != axes::Result::ok) {
    // The stop from a state inside the limits always plans; if not, end where the axis is.
    std::abort();
  }
  a.profile = p;
  a.k = 0;
  a.t = 0.0;
  a.mode = Mode::stopping;
  return true;
}

bool IndpAxes::stop(std::size_t i) noexcept {
  Axis& a = axes_[i];
  if (a.mode == Mode::idle) return false;
  a.interruptible = false;
  axes::Profile p;
  if (axes::plan_stop(state(a), a.dynamics, p) != axes::Result::ok) {
    std::abort();  // the stop from a state inside the limits always plans
  }
  a.profile = p;
  a.k = 0;
  a.t = 0.0;
  a.mode = Mode::stopping;
  return true;
}

bool IndpAxes::hand_over(std::size_t i) noexcept {
  if (!interruptible(i)) return false;
  Axis& a = axes_[i];
  a.interruptible = false;
  a.mode = Mode::idle;
  a.target = a.sp.p;
  a.owned = false;
  return true;
}

void IndpAxes::step() noexcept {
  for (Axis& a : axes_) {
    if (a.mode == Mode::idle) continue;
    ++a.k;
    a.t = static_cast<double>(a.k) * t_cycle_;
    // Whole cycles, never shorter (the rounding of every wait, docs/ipo.md).
    if (a.t < a.profile.duration() * (1.0 - kRelRounding)) {
      a.sp = a.profile.at(a.t);
      continue;
    }
    switch (a.mode) {
      case Mode::moving:
        a.sp = axes::Setpoint{a.target, 0.0, 0.0, 0.0};  // on the target bit for bit
        a.mode = Mode::idle;
        a.interruptible = false;
        break;
      case Mode::stopping:
        a.sp = a.profile.at(a.t);
        a.sp.j = 0.0;
        a.target = a.sp.p;  // the interrupted motion ends where it stopped
        a.mode = Mode::idle;
        break;
      case Mode::held:
        a.sp = a.profile.at(a.t);  // at rest, target kept
        a.sp.j = 0.0;
        break;
      case Mode::idle:
        break;
    }
  }
}

planner::AxisMask IndpAxes::owned_mask() const noexcept {
  planner::AxisMask m = 0;
  for (std::size_t i = 0; i < axes_.size(); ++i)
    if (axes_[i].owned) m |= planner::AxisMask{1} << i;
  return m;
}

bool IndpAxes::in_position_mask(planner::AxisMask mask) const noexcept {
  for (std::size_t i = 0; i < axes_.size(); ++i)
    if ((mask == 0 || ((mask >> i) & 1u) != 0) && !in_position(i)) return false;
  return true;
}

}  // namespace ncsim::channel

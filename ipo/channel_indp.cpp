// ipo/channel_indp: the channel's INDP axes per cycle and the scenario's axis override (see
// ipo/channel.hpp and docs/ipo.md "INDP axes and technology functions").

#include <cmath>
#include <cstdio>
#include <string>

#include "ipo/channel.hpp"

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
  planner::AxisMask owned = indp_.owned_mask();
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
             "not supported: axis " + axes_[i].config.name +
                 " programmed as a path axis while its INDP motion " +
                 (indp_.in_position(i) ? "left it at " + number(p) + " (the block starts at " +
                                             number(m.start[i]) + ")"
                                       : "runs (to " + number(indp_.target(i)) + ")") +
                 "; program #WAIT INDP before (P-CHAN-00451 implicit synchronisation)",
             c, static_cast<int>(i));
        return false;
      }
      indp_.release(i);
      owned &= ~(planner::AxisMask{1} << i);
    }
  }
  patched_ = c;
  patched_.independent = owned;
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    if (((owned >> i) & 1u) == 0) continue;
    const axes::Setpoint& sp = indp_.setpoint(i);
    setpoint_[i] = sp;
    patched_.x[i] = sp.p;
    patched_.v[i] = sp.v;
    patched_.a[i] = sp.a;
    patched_.j[i] = sp.j;
  }
  shown_ = &patched_;
  return true;
}

bool Channel::indp_override(const scenario::AxisOverride& o, const Cycle& at) noexcept {
  std::size_t i = 0;
  while (i < axes_.size() && axes_[i].config.name != o.axis)
    ++i;
  if (i == axes_.size()) {
    stop(kIndpOverrideId,
         "scenario axis override of " + o.axis +
             ": not an axis of the channel (spindles, the conveyor and encoder axes move no INDP "
             "motion)",
         at, -1);
    return false;
  }
  // 002_* 2.2: ignored_braking_phase / rejected_stopping keep the value for later.
  if (indp_.set_override(i, o.fraction) == axes::Result::error_invalid_input) {
    stop(kIndpOverrideId,
         "scenario axis override of " + o.axis + " = " + number(o.fraction * 100.0) +
             " % outside 0 .. 100 % (002_* 2.2)",
         at, static_cast<int>(i));
    return false;
  }
  return true;
}

}  // namespace ncsim::ipo

#include "program/machine_axes.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace ncsim::program {

using machines::AxisKind;

std::vector<std::uint8_t> interpolated_axes(const machines::Machine& machine) {
  std::vector<std::uint8_t> out;
  const machines::AxisParams* conveyor = machine.conveyor_axis();
  for (std::size_t i = 0; i < machine.axes.size(); ++i) {
    const machines::AxisParams& a = machine.axes[i];
    if (a.kind == AxisKind::spindle || a.encoder_only || &a == conveyor) continue;
    out.push_back(static_cast<std::uint8_t>(i));
  }
  return out;
}

ipo::Config machine_config(const machines::Machine& machine, double t_cycle) {
  ipo::Config c;
  for (const std::uint8_t i : interpolated_axes(machine)) {
    const machines::Dynamics& d = machine.axes[i].dynamics;
    planner::AxisLimits l;
    l.v_max = d.v_max;                          // P-AXIS-00212
    l.v_reference = d.v_max;                    // ISG has no reference-velocity key
    l.v_rapid = d.v_rapid;                      // P-AXIS-00209
    l.a_max = std::min(d.acc_feed, d.acc_max);  // P-AXIS-00001 capped by P-AXIS-00008
    l.d_max = std::min(d.dec_feed, d.acc_max);  // P-AXIS-00002 capped by P-AXIS-00008
    l.j_max = d.jerk_feed();
    l.c0 = d.velo_jump_factor;  // NCSIM-AXIS-020
    // G00 slope: P-AXIS-00004 capped by P-AXIS-00008; jerk P-AXIS-00004 / P-AXIS-00200.
    l.a_rapid = std::min(d.acc_rapid, d.acc_max);
    l.j_rapid = d.ramp_rapid > 0.0 ? d.jerk_rapid() : 0.0;
    c.axes.push_back(l);
    const machines::Monitoring& m = machine.axes[i].monitoring;
    c.exact_stop.push_back({m.exact_stop_window, m.settling_time.value_or(0.0)});
  }
  c.channel.t_cycle = t_cycle;
  if (machine.channel.conveyor)  // NCSIM-CHAN-640
    c.channel.belt_reserve = machine.channel.conveyor->dynamics_reserve;
  // P-CHAN-00009 corr_v_trans_jerk: the C1 rule on or off (docs/planner.md "Corners").
  c.channel.limit_c1_by_jerk = machine.channel.corr_v_trans_jerk;
  c.window = static_cast<std::size_t>(machine.channel.interpolator.look_ahead_blocks);
  switch (machine.channel.path_override_type) {  // NCSIM-CHAN-630 (000 §7.5.6)
    case machines::PathOverrideType::reduced:
      c.override_type = ipo::OverrideType::reduced;
      break;
    case machines::PathOverrideType::original:
      c.override_type = ipo::OverrideType::original;
      break;
    case machines::PathOverrideType::reduced_above_100:
      c.override_type = ipo::OverrideType::reduced_above_100;
      break;
  }
  return c;
}

AxisLayout::AxisLayout(const machines::Machine& machine)
    : axes(interpolated_axes(machine)), slot(machine.axes.size(), -1) {
  if (axes.empty() || axes.size() > planner::kMaxAxes) {
    throw std::invalid_argument(
        "machine '" + machine.name + "' has " + std::to_string(axes.size()) +
        " interpolated axes; the path interpolator needs 1.." + std::to_string(planner::kMaxAxes));
  }
  for (std::size_t k = 0; k < axes.size(); ++k) {
    slot[axes[k]] = static_cast<int>(k);
    if (machine.axes[axes[k]].kind == AxisKind::linear) path_axes |= planner::AxisMask{1} << k;
  }
  if (path_axes == 0) path_axes = (planner::AxisMask{1} << axes.size()) - 1;
  const char* names[3] = {"X", "Y", "Z"};
  for (std::size_t k = 0; k < 3; ++k) {
    const machines::AxisParams* a = machine.find_axis(names[k]);
    if (a != nullptr) xyz[k] = static_cast<int>(a - machine.axes.data());
  }
}

}  // namespace ncsim::program

// channel/exact_stop: G60 / G360 exact stops on actual positions (see the header).

#include "channel/exact_stop.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/number_text.hpp"
#include "core/tolerance.hpp"

namespace ncsim::channel {

ExactStopWait::ExactStopWait(double wait_max, double t_cycle)
    : wait_max_(wait_max), t_cycle_(t_cycle) {
  if (!(wait_max_ > 0.0))
    throw std::invalid_argument("channel::Channel: exact_stop_wait_max must be > 0 s, got " +
                                core::human(wait_max_));
  // Same rounding as every wait (docs/ipo.md): the limit in whole cycles, never shorter.
  wait_cycles_max_ = static_cast<std::uint64_t>(std::ceil(wait_max_ / t_cycle_ - kCycleRounding));
}

void ExactStopWait::begin(const ipo::Cycle& c, std::span<const axes::Setpoint> setpoints,
                          bool transformed) noexcept {
  active_ = true;
  waited_ = 0;
  moved_ = 0;
  for (std::size_t i = 0; i < setpoints.size(); ++i)
    target_[i] = setpoints[i].p;  // the joints' end point under #TRAFO
  if (const planner::Move* prog = c.programmed) {
    for (std::size_t i = 0; i < setpoints.size(); ++i) {
      const bool moved = prog->end[i] != prog->start[i] ||
                         (prog->arc && (prog->arc->axis_1 == i || prog->arc->axis_2 == i));
      // Every joint of a transformed block is waited for.
      if (moved || transformed) moved_ |= 1u << i;
    }
  }
}

bool ExactStopWait::check(const ipo::Cycle& c, const AxisStage& axes, bool& release,
                          std::optional<RunTimeError>& error) noexcept {
  bool all_in = true;
  for (std::size_t i = 0; i < axes.size(); ++i)
    if (((moved_ >> i) & 1u) != 0 && !axes.in_window(i)) all_in = false;
  if (all_in) {
    release = true;
    active_ = false;
    return true;
  }
  if (c.activity == ipo::Activity::exact_stop) ++waited_;  // the stop cycle itself counts 0
  if (waited_ <= wait_cycles_max_) return true;
  int worst = 0;
  double worst_d = -1.0;
  for (std::size_t i = 0; i < axes.size(); ++i) {
    const double d = std::fabs(target_[i] - axes.state().actual[i]);
    if (((moved_ >> i) & 1u) != 0 && !axes.in_window(i) && d > worst_d) {
      worst = static_cast<int>(i);
      worst_d = d;
    }
  }
  const ChannelAxis& w = axes.config(static_cast<std::size_t>(worst));
  raise(error, kExactStopWaitId,
        "axis " + w.name + ": exact stop window P-AXIS-00236 (" +
            core::human(w.monitor.exact_stop.window) + " mm) not reached, " + core::human(worst_d) +
            " mm from the target after " + core::human(waited()) +
            " s (P-AXIS-00532 does not monitor the time; ncsim's limit " + core::human(wait_max_) +
            " s)",
        c, worst);
  return false;
}

}  // namespace ncsim::channel

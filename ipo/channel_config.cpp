// ipo/channel_config: a machine's channel configuration (see ipo/channel.hpp).

#include <stdexcept>

#include "axes/axis_config.hpp"
#include "ipo/channel.hpp"
#include "ipo/program_source.hpp"

namespace ncsim::ipo {

ChannelConfig channel_config(const machines::Machine& machine, double t_cycle) {
  ChannelConfig c;
  c.path = machine_config(machine, t_cycle);
  for (const std::uint8_t i : interpolated_axes(machine)) {
    const machines::AxisParams& axis = machine.axes[i];
    ChannelAxis a;
    a.name = axis.name;
    a.control = axes::make_position_control(axis);  // P-AXIS-00099, NCSIM-AXIS-023
    a.monitor = axes::make_monitor_params(axis);    // P-AXIS-00177/178/236/532, NCSIM-AXIS-024..
    a.indp = indp_axis_config(axis);  // --- indp: G01 / G00 dynamics, soft limits, rule
    a.indp.machine_index = i;
    c.axes.push_back(std::move(a));
  }
  return c;
}

}  // namespace ncsim::ipo

// channel/channel_config: a machine's channel configuration (see channel/channel.hpp).

#include <array>
#include <stdexcept>
#include <utility>

#include "axes/axis_config.hpp"
#include "channel/channel.hpp"
#include "program/program_source.hpp"

namespace ncsim::channel {

ChannelConfig channel_config(const machines::Machine& machine, double t_cycle) {
  ChannelConfig c;
  c.path = program::machine_config(machine, t_cycle);
  // With a kinematic, transformed Moves are limited by the joints (program/trafo.hpp).
  if (auto trafo = program::machine_trafo(machine, c.path)) {
    c.forward = program::forward_map(trafo->kinematics, trafo->slots);
    c.path.joints = std::move(trafo->limits);
  }
  for (const std::uint8_t i : program::interpolated_axes(machine)) {
    const machines::AxisParams& axis = machine.axes[i];
    ChannelAxis a;
    a.name = axis.name;
    a.control = axes::make_position_control(axis);  // P-AXIS-00099, NCSIM-AXIS-023
    a.monitor = axes::make_monitor_params(axis);    // P-AXIS-00177/178/236/532, NCSIM-AXIS-024..
    a.indp = indp_axis_config(axis);                // G01 / G00 dynamics, soft limits, rule
    a.indp.machine_index = i;
    a.reference_position = axis.reference_position;  // G74, P-AXIS-00152
    a.homing_velocity = axis.homing_velocity;        // G74, P-AXIS-00219
    c.axes.push_back(std::move(a));
  }
  // Conveyor tracking (docs/conveyor.md "Synchronisation")
  if (machine.channel.conveyor) {
    c.conveyor = machine.channel.conveyor;
    if (const machines::AxisParams* belt = machine.conveyor_axis())
      c.conveyor_axis = belt->conveyor;
    const std::array<const char*, 3> xyz{"X", "Y", "Z"};
    for (const std::uint8_t i : program::interpolated_axes(machine)) {
      const machines::AxisParams& axis = machine.axes[i];
      tracking::SyncAxis a;
      a.name = axis.name;
      for (int k = 0; k < 3; ++k)  // X, Y, Z as the interpreter and ProgramSource find them
        if (machine.find_axis(xyz[static_cast<std::size_t>(k)]) == &axis) a.xyz = k;
      // The catch-up's V is P-AXIS-00212 (the target moves: the conveying axis must exceed the
      // belt, which 50587 keeps below it); A+, A-, J are the PTP generator's.
      a.dynamics = axes::make_generator_config(axis).dynamics;
      a.dynamics.v_max = axis.dynamics.v_max;
      c.sync_axes.push_back(std::move(a));
    }
  }
  return c;
}

}  // namespace ncsim::channel

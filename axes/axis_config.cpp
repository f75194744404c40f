#include "axes/axis_config.hpp"

#include <stdexcept>
#include <string>

#include "core/number_text.hpp"

namespace ncsim::axes {

GeneratorConfig make_generator_config(const machines::AxisParams& axis) {
  const machines::Dynamics& d = axis.dynamics;
  GeneratorConfig config;
  config.dynamics.v_max = d.v_rapid;      // P-AXIS-00209
  config.dynamics.a_max = d.acc_feed;     // P-AXIS-00001
  config.dynamics.d_max = d.dec_feed;     // P-AXIS-00002
  config.dynamics.j_max = d.jerk_feed();  // P-AXIS-00001/00002 over P-AXIS-00195..00198
  config.v_axis_max = d.v_max;            // P-AXIS-00212
  config.increment = kListIncrement;
  config.profile_rule =  // NCSIM-AXIS-030
      d.time_optimal_profiles ? ProfileRule::time_optimal : ProfileRule::manual;
  return config;
}

PositionControlParams make_position_control(const machines::AxisParams& axis) {
  PositionControlParams params;
  params.kv = axis.control.kv;                    // P-AXIS-00099
  params.drive_pt1_time = axis.control.pt1_time;  // NCSIM-AXIS-023
  params.noise_seed = static_cast<std::uint64_t>(axis.number);
  return params;
}

AxisMonitorParams make_monitor_params(const machines::AxisParams& axis) {
  AxisMonitorParams params;
  // Soft limits (P-AXIS-00177/00178) bound linear and rotary axes; a spindle or a modulo axis
  // turns without end (ncsim decision, docs/machines.md).
  const bool bounded = axis.kind != machines::AxisKind::spindle && !axis.modulo;
  params.soft_limits.min_enabled = bounded;
  params.soft_limits.max_enabled = bounded;
  params.soft_limits.min_position = axis.soft_limits.neg;
  params.soft_limits.max_position = axis.soft_limits.pos;

  const machines::Monitoring& m = axis.monitoring;
  params.lag.enabled = m.position_lag;                       // NCSIM-AXIS-024
  params.lag.max_lag = m.position_lag_max;                   // NCSIM-AXIS-025
  params.lag.filter_time = m.position_lag_filter_time;       // NCSIM-AXIS-026
  params.target_position.enabled = m.target_position;        // NCSIM-AXIS-027
  params.target_position.window = m.target_position_window;  // NCSIM-AXIS-028
  params.target_position.time = m.target_position_time;      // NCSIM-AXIS-029
  params.exact_stop.window = m.exact_stop_window;            // P-AXIS-00236
  // P-AXIS-00532: the loader keeps only a positive time; "not monitored" is 0 here.
  params.exact_stop.settling_time = m.settling_time.value_or(0.0);
  params.exact_stop.legacy_settling_time = 0.0;
  return params;
}

std::optional<ModuloParams> make_modulo_params(const machines::AxisParams& axis) {
  if (!axis.modulo) return std::nullopt;
  if (axis.modulo_lower != 0.0) {
    throw std::invalid_argument(
        "not supported: axis " + axis.name +
        " getriebe[0].modulou (P-AXIS-00127) = " + core::number_text(axis.modulo_lower) +
        "; the axis core counts modulo positions from 0 (docs/machines.md)");
  }
  ModuloParams params;
  params.factor = axis.modulo_upper - axis.modulo_lower;  // P-AXIS-00126 - P-AXIS-00127
  return params;
}

AxisConfig make_axis_config(const machines::AxisParams& axis) {
  return AxisConfig{make_generator_config(axis), make_position_control(axis),
                    make_monitor_params(axis), make_modulo_params(axis)};
}

std::vector<AxisConfig> make_axis_configs(const machines::Machine& machine) {
  std::vector<AxisConfig> configs;
  configs.reserve(machine.axes.size());
  for (const machines::AxisParams& axis : machine.axes) {
    configs.push_back(make_axis_config(axis));
  }
  return configs;
}

}  // namespace ncsim::axes

// ipo/machine_data: see machine_data.hpp.

#include "ipo/machine_data.hpp"

namespace ncsim::ipo {

bool set_conveyor_filter_param(machines::ConveyorAxisParams& params, std::string_view key,
                               double value) {
  const int order = static_cast<int>(value);  // uns32 0..1000, checked at decode (param_table)
  if (key == "conv_sync.enable_filter") {
    params.enable_filter = value != 0.0;
  } else if (key == "conv_sync.type_pos_filter") {
    params.type_pos_filter = order;
  } else if (key == "conv_sync.order_pos_filter") {
    params.order_pos_filter = order;
  } else if (key == "conv_sync.order_v_filter") {
    params.order_v_filter = order;
  } else if (key == "conv_sync.order_post_v_filter") {
    params.order_post_v_filter = order;
  } else if (key == "conv_sync.order_v_filter_dyn") {
    params.order_v_filter_dyn = order;
  } else if (key == "conv_sync.delay_time") {
    params.delay_time = value;
  } else {
    return false;
  }
  return true;
}

std::optional<std::string> machine_data_unsupported(const interp::MachineData& command,
                                                    const machines::Machine& machine) {
  const machines::AxisParams* axis =
      command.axis && *command.axis < machine.axes.size() ? &machine.axes[*command.axis] : nullptr;
  machines::ConveyorAxisParams scratch;
  for (const interp::MachineSetting& s : command.settings) {
    if (axis != nullptr && axis->conveyor && set_conveyor_filter_param(scratch, s.key, s.value))
      continue;
    return "#MACHINE DATA of " + std::string(s.id) + " (" + std::string(s.key) + ")" +
           (axis != nullptr ? " on axis " + axis->name : std::string()) +
           ": while a program runs ncsim changes only the conveyor axis's actual-value filters "
           "and delay time (P-AXIS-00620, P-AXIS-00623..00626, NCSIM-AXIS-005/006; seed 004 "
           "2.1.4)";
  }
  if (command.settings.empty()) return "#MACHINE DATA without a parameter ncsim changes";
  return std::nullopt;
}

machines::ConveyorAxisParams apply_machine_data(machines::ConveyorAxisParams current,
                                                const interp::MachineData& command) {
  for (const interp::MachineSetting& s : command.settings)
    set_conveyor_filter_param(current, s.key, s.value);
  return current;
}

}  // namespace ncsim::ipo

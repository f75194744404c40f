// program/machine_data: see machine_data.hpp.

#include "program/machine_data.hpp"

#include "machines/conveyor_params.hpp"

namespace ncsim::program {

std::optional<std::string> machine_data_unsupported(const interp::MachineData& command,
                                                    const machines::Machine& machine) {
  const machines::AxisParams* axis =
      command.axis && *command.axis < machine.axes.size() ? &machine.axes[*command.axis] : nullptr;
  for (const interp::MachineSetting& s : command.settings) {
    if (axis != nullptr && axis->conveyor && machines::find_conveyor_filter_param(s.key) != nullptr)
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
    if (const machines::ConveyorFilterParam* f = machines::find_conveyor_filter_param(s.key))
      f->set(current, s.value);
  return current;
}

}  // namespace ncsim::program

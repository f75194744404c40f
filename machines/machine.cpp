#include "machines/machine.hpp"

#include <algorithm>

namespace ncsim::machines {

double Dynamics::jerk_feed() const {
  return std::min({acc_feed / ramp_acc_up, acc_feed / ramp_acc_down, dec_feed / ramp_dec_up,
                   dec_feed / ramp_dec_down});
}

const AxisParams* Machine::find_axis(std::string_view program_name) const {
  for (const AxisParams& axis : axes) {
    if (axis.name == program_name) return &axis;
  }
  // "S" and "S1" name the same (first) spindle.
  const std::string_view alias =
      program_name == "S" ? "S1" : (program_name == "S1" ? "S" : std::string_view{});
  if (alias.empty()) return nullptr;
  for (const AxisParams& axis : axes) {
    if (axis.kind == AxisKind::spindle && axis.name == alias) return &axis;
  }
  return nullptr;
}

const AxisParams* Machine::find_axis_number(int number) const {
  for (const AxisParams& axis : axes) {
    if (axis.number == number) return &axis;
  }
  return nullptr;
}

const AxisParams* Machine::conveyor_axis() const {
  for (const AxisParams& axis : axes) {
    if (axis.conveyor) return &axis;
  }
  return nullptr;
}

std::optional<SoftLimits> Machine::soft_limits(std::string_view program_name) const {
  if (const AxisParams* axis = find_axis(program_name)) return axis->soft_limits;
  return std::nullopt;
}

}  // namespace ncsim::machines

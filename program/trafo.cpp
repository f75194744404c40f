// program/trafo: the machine's kinematic transform for the interpolator and the channel (see the
// header).

#include "program/trafo.hpp"

#include <utility>

#include "program/program_source.hpp"

namespace ncsim::program {

namespace {

// Maps the kinematic's slots (at `slots`) of an axis vector through `inverse` ? the kinematic's
// inverse : its forward transform; every other axis passes unchanged.
planner::JointMap slot_map(std::shared_ptr<const machines::Kinematics> kinematics,
                           std::array<int, machines::kKinAxes> slots, bool inverse) {
  return [kin = std::move(kinematics), slots, inverse](const planner::AxisVec& x,
                                                       planner::AxisVec& q) noexcept {
    machines::KinAxes p{};
    for (std::size_t k = 0; k < slots.size(); ++k)
      if (slots[k] >= 0) p[k] = x[static_cast<std::size_t>(slots[k])];
    machines::KinAxesResult r;
    try {
      r = inverse ? kin->inverse_axes(p) : kin->forward_axes(p);
    } catch (...) {
      return false;
    }
    if (!r.ok()) return false;
    q = x;
    for (std::size_t k = 0; k < slots.size(); ++k)
      if (slots[k] >= 0) q[static_cast<std::size_t>(slots[k])] = r.value[k];
    return true;
  };
}

}  // namespace

planner::JointMap joint_map(std::shared_ptr<const machines::Kinematics> kinematics,
                            std::array<int, machines::kKinAxes> slots) {
  return slot_map(std::move(kinematics), slots, true);
}

planner::JointMap forward_map(std::shared_ptr<const machines::Kinematics> kinematics,
                              std::array<int, machines::kKinAxes> slots) {
  return slot_map(std::move(kinematics), slots, false);
}

std::optional<MachineTrafo> machine_trafo(const machines::Machine& machine,
                                          const ipo::Config& config) {
  if (machine.channel.trafos.empty()) return std::nullopt;
  const machines::TrafoParams& t = machine.channel.trafos.front();
  machines::KinematicsBuild built = machines::make_kinematics(t.type != 0 ? t.type : t.id, t.param);
  if (built.error || !built.kinematics) return std::nullopt;
  MachineTrafo m;
  m.kin_id = t.id;
  m.kinematics = std::move(built.kinematics);
  const std::vector<std::uint8_t> axes = interpolated_axes(machine);
  for (std::size_t k = 0; k < m.kinematics->axis_count(); ++k)
    for (std::size_t s = 0; s < axes.size(); ++s)
      if (machine.axes[axes[s]].name == machines::kKinAxisNames[k])
        m.slots[k] = static_cast<int>(s);
  for (std::size_t k = 0; k < 3; ++k)
    m.xyz[k] = m.slots[k];
  m.limits.inverse = joint_map(m.kinematics, m.slots);
  m.limits.joints = config.axes;  // the joints are the machine axes, with their own limits
  m.limits.cartesian = config.axes;
  for (const int s : m.slots) {
    if (s < 0) continue;
    planner::AxisLimits& c = m.limits.cartesian[static_cast<std::size_t>(s)];
    c.v_max = c.v_reference = c.v_rapid = kCartesianUnlimitedV;
    c.a_max = c.d_max = kCartesianUnlimitedA;
    c.j_max = kCartesianUnlimitedJ;
    c.a_rapid = c.j_rapid = 0.0;  // G00 keeps the feed values: the joints limit
  }
  return m;
}

}  // namespace ncsim::program

// program/trafo: the machine's kinematic transform for the interpolator and the channel (see the
// header).

#include "program/trafo.hpp"

#include <utility>

#include "program/program_source.hpp"

namespace ncsim::program {

namespace {

// Maps X, Y, Z (at `xyz`) of an axis vector through `inverse` ? the kinematic's inverse : its
// forward transform; every other axis passes unchanged.
planner::JointMap xyz_map(std::shared_ptr<const machines::Kinematics> kinematics,
                          std::array<int, 3> xyz, bool inverse) {
  return [kin = std::move(kinematics), xyz, inverse](const planner::AxisVec& x,
                                                     planner::AxisVec& q) noexcept {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < 3; ++k)
      if (xyz[k] >= 0) p[static_cast<Eigen::Index>(k)] = x[static_cast<std::size_t>(xyz[k])];
    machines::KinResult r;
    try {
      r = inverse ? kin->inverse(p) : kin->forward(p);
    } catch (...) {
      return false;
    }
    if (!r.ok()) return false;
    q = x;
    for (std::size_t k = 0; k < 3; ++k)
      if (xyz[k] >= 0) q[static_cast<std::size_t>(xyz[k])] = r.value[static_cast<Eigen::Index>(k)];
    return true;
  };
}

}  // namespace

planner::JointMap joint_map(std::shared_ptr<const machines::Kinematics> kinematics,
                            std::array<int, 3> xyz) {
  return xyz_map(std::move(kinematics), xyz, true);
}

planner::JointMap forward_map(std::shared_ptr<const machines::Kinematics> kinematics,
                              std::array<int, 3> xyz) {
  return xyz_map(std::move(kinematics), xyz, false);
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
  const char* names[3] = {"X", "Y", "Z"};
  for (std::size_t k = 0; k < 3; ++k)
    for (std::size_t s = 0; s < axes.size(); ++s)
      if (machine.axes[axes[s]].name == names[k]) m.xyz[k] = static_cast<int>(s);
  m.limits.inverse = joint_map(m.kinematics, m.xyz);
  m.limits.joints = config.axes;  // the joints are the machine axes, with their own limits
  m.limits.cartesian = config.axes;
  for (const int s : m.xyz) {
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

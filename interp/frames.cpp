// interp/frames.cpp: the decoder keeps one position in the frame `frame()` names. When a command
// changes the frame, the position is re-based into the new one as the kernel does, so that the
// next motion starts where the tool is, in the frame of its end:
// - #CS ON / OFF / OFF ALL: p_new = F_new^-1(F_old(p)), F the composed #CS chain (decode time);
// - #TRAFO ON / OFF: the X/Y/Z axis values go through the kinematic's forward / inverse
//   transform (decode time; a failing transform is the kinematic's error at the #TRAFO line);
// - #SYNC IN / OUT: PCS1 = T0^-1(MCS) shifted by the belt travel since the latch, which only
//   the run time knows: the interpreter asks for it with a Barrier; the decode-only answer is
//   the belt travel 0 (interp/interpreter.hpp "decode-only state").
#include "interp/frames.hpp"

#include <string>

namespace ncsim::interp {

Frames::Frames(const machines::Machine& machine, const machines::CsStack& cs,
               const ModalSnapshot& modal, const Xyz& xyz)
    : machine_(machine), cs_(cs), modal_(modal), xyz_(xyz) {
  for (std::size_t i = 0; i < machine.axes.size() && i < kMaxAxes; ++i)
    for (std::size_t k = 0; k < 3; ++k)
      if (machine.axes[i].name == machines::kKinAxisNames[3 + k])
        abc_[k] = static_cast<std::uint8_t>(i);
}

CoordFrame Frames::frame() const {
  CoordFrame f;
  f.cs_depth = static_cast<std::uint8_t>(cs_.active_count());
  f.space = modal_.synchronised ? Space::pcs1 : (f.cs_depth > 0 ? Space::pcs : Space::mcs);
  f.kinematics = modal_.kinematics_on;
  return f;
}

Eigen::Vector3d Frames::xyz_of(const AxisValues& values) const {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) {
    if (xyz_[static_cast<std::size_t>(k)]) p[k] = values[*xyz_[static_cast<std::size_t>(k)]];
  }
  return p;
}

void Frames::set_xyz(AxisValues& values, const Eigen::Vector3d& p) const {
  for (int k = 0; k < 3; ++k) {
    if (xyz_[static_cast<std::size_t>(k)]) values[*xyz_[static_cast<std::size_t>(k)]] = p[k];
  }
}

void Frames::rebase_cs(const machines::Frame& before, AxisValues& position) const {
  // p_parent = F(p_child); the parent (MCS side) point stays where it is.
  const machines::Frame after = cs_.active_frame();
  set_xyz(position, after.inverse().apply(before.apply(xyz_of(position))));
}

std::optional<machines::KinError> Frames::rebase_trafo(bool on, std::optional<int> kin_id,
                                                       AxisValues& position) {
  if (!kinematic_ || kinematic_->id() != kin_id.value_or(-1)) {
    kinematic_.reset();
    const machines::TrafoParams* params = nullptr;
    for (const auto& t : machine_.channel.trafos) {
      if (t.id == kin_id) params = &t;
    }
    if (params == nullptr) {
      return machines::KinError{"292005", "kinematic id " + std::to_string(kin_id.value_or(0)) +
                                              " is not configured on machine " + machine_.name};
    }
    machines::KinematicsBuild built =
        machines::make_kinematics(params->type != 0 ? params->type : params->id, params->param);
    if (built.error) return built.error;
    kinematic_ = std::move(built.kinematics);
  }
  // The #CS chain (if any) stays; the transform acts below it, on its parent coordinates (the
  // position; A, B, C of a 6-axis kinematic are MCS angles, docs/machines.md "Kinematic 45").
  const machines::Frame f = cs_.active_frame();
  const Eigen::Vector3d parent = f.apply(xyz_of(position));
  machines::KinAxes in{parent.x(), parent.y(), parent.z(), 0.0, 0.0, 0.0};
  for (std::size_t k = 0; k < 3; ++k)
    if (abc_[k]) in[3 + k] = position[*abc_[k]];
  const machines::KinAxesResult r =
      on ? kinematic_->forward_axes(in) : kinematic_->inverse_axes(in);
  if (!r.ok()) {
    return machines::KinError{
        r.error->id, std::string(on ? "#TRAFO ON" : "#TRAFO OFF") +
                         ": the current position cannot be transformed: " + r.error->message};
  }
  set_xyz(position, f.inverse().apply(Eigen::Vector3d(r.value[0], r.value[1], r.value[2])));
  for (std::size_t k = 0; k < 3 && kinematic_->axis_count() > 3; ++k)
    if (abc_[k]) position[*abc_[k]] = r.value[3 + k];
  return std::nullopt;
}

AxisValues Frames::sync_rebased(bool in, const AxisValues& position) const {
  // PCS1 at the latch is PCS0 (seed 004 §2.1); PCS0 -> MCS is T0 (P-CHAN-00368..00373). With
  // the belt travel since the latch s: p_pcs1 = T0^-1(p_mcs) - s * e_conveying. s is run-time
  // state; this is the value for s = 0.
  AxisValues p = position;
  if (!machine_.channel.conveyor) return p;
  const machines::Frame t0 = machine_.channel.conveyor->t0();
  set_xyz(p, in ? t0.inverse().apply(xyz_of(position)) : t0.apply(xyz_of(position)));
  return p;
}

}  // namespace ncsim::interp

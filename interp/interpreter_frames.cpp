// interp/interpreter_frames.cpp: the frame the interpreter's position is in, and its re-basing
// at #CS, #TRAFO and #SYNC IN/OUT (docs/interp.md "Frames").
//
// The interpreter keeps one current position (`Impl::position`) in the frame `Impl::frame()`
// names. When a command changes the frame, the position is re-based into the new frame the way
// the kernel does, so that the next motion starts where the tool is, in the frame of its end:
// - #CS ON / OFF / OFF ALL: p_new = F_new^-1(F_old(p)), F the composed #CS chain (decode time);
// - #TRAFO ON / OFF: the X/Y/Z axis values go through the kinematic's forward / inverse
//   transform (decode time; a failing transform is the kinematic's error at the #TRAFO line);
// - #SYNC IN / OUT: PCS1 = T0^-1(MCS) shifted by the belt travel since the latch, which only
//   the run time knows: the interpreter asks for it with a Barrier; the decode-only answer is
//   the belt travel 0 (interp/interpreter.hpp "decode-only state").
#include "interp/interpreter_impl.hpp"
#include "machines/kinematics.hpp"

namespace ncsim::interp {

CoordFrame Interpreter::Impl::frame() const {
  CoordFrame f;
  f.cs_depth = static_cast<std::uint8_t>(cs.active_count());
  f.space = modal.synchronised ? Space::pcs1 : (f.cs_depth > 0 ? Space::pcs : Space::mcs);
  f.kinematics = modal.kinematics_on;
  return f;
}

Eigen::Vector3d Interpreter::Impl::xyz_of(const AxisValues& values) const {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) {
    if (xyz[static_cast<std::size_t>(k)]) p[k] = values[*xyz[static_cast<std::size_t>(k)]];
  }
  return p;
}

void Interpreter::Impl::set_xyz(AxisValues& values, const Eigen::Vector3d& p) const {
  for (int k = 0; k < 3; ++k) {
    if (xyz[static_cast<std::size_t>(k)]) values[*xyz[static_cast<std::size_t>(k)]] = p[k];
  }
}

void Interpreter::Impl::rebase_cs(const machines::Frame& before) {
  // p_parent = F(p_child); the parent (MCS side) point stays where it is.
  const machines::Frame after = cs.active_frame();
  set_xyz(position, after.inverse().apply(before.apply(xyz_of(position))));
}

bool Interpreter::Impl::rebase_trafo(bool on, core::SourceLoc at) {
  if (!kinematic || kinematic->id() != kin_id.value_or(-1)) {
    kinematic.reset();
    const machines::TrafoParams* params = nullptr;
    for (const auto& t : machine.channel.trafos) {
      if (t.id == kin_id) params = &t;
    }
    if (params == nullptr) {
      return fail(at, "292005",
                  "kinematic id " + std::to_string(kin_id.value_or(0)) +
                      " is not configured on machine " + machine.name);
    }
    machines::KinematicsBuild built =
        machines::make_kinematics(params->type != 0 ? params->type : params->id, params->param);
    if (built.error) return fail(at, built.error->id, built.error->message);
    kinematic = std::move(built.kinematics);
  }
  // The #CS chain (if any) stays; the transform acts below it, on its parent coordinates.
  const machines::Frame f = cs.active_frame();
  const Eigen::Vector3d parent = f.apply(xyz_of(position));
  const machines::KinResult r = on ? kinematic->forward(parent) : kinematic->inverse(parent);
  if (!r.ok()) {
    return fail(at, r.error->id,
                std::string(on ? "#TRAFO ON" : "#TRAFO OFF") +
                    ": the current position cannot be transformed: " + r.error->message);
  }
  set_xyz(position, f.inverse().apply(r.value));
  return true;
}

AxisValues Interpreter::Impl::sync_rebased(bool in) const {
  // PCS1 at the latch is PCS0 (seed 004 §2.1); PCS0 -> MCS is T0 (P-CHAN-00368..00373). With
  // the belt travel since the latch s: p_pcs1 = T0^-1(p_mcs) - s * e_conveying. s is run-time
  // state; this is the value for s = 0.
  AxisValues p = position;
  if (!machine.channel.conveyor) return p;
  const machines::Frame t0 = machine.channel.conveyor->t0();
  set_xyz(p, in ? t0.inverse().apply(xyz_of(position)) : t0.apply(xyz_of(position)));
  return p;
}

}  // namespace ncsim::interp

#pragma once
// interp/frames: the frame the decoder's position is in, and its re-basing at #CS, #TRAFO and
// #SYNC IN/OUT (docs/interp.md "Frames"). Inputs: the machine, the decoder's #CS chain, modal
// state and X/Y/Z indices (references). Outputs: a command's frame, the position re-based.
// Invariant: a re-based position is the same machine point (#SYNC: at belt travel 0).

#include <array>
#include <cstdint>
#include <memory>
#include <optional>

#include "interp/command.hpp"
#include "machines/cs_stack.hpp"
#include "machines/kinematics.hpp"
#include "machines/machine.hpp"

namespace ncsim::interp {

class Frames {
 public:
  using Xyz = std::array<std::optional<std::uint8_t>, 3>;  // machine indices of X, Y, Z
  Frames(const machines::Machine& machine, const machines::CsStack& cs, const ModalSnapshot& modal,
         const Xyz& xyz);

  CoordFrame frame() const;  // the frame the decoder's position is in
  /// After #CS ON/OFF changed the chain from `before`: p_new = F_new^-1(F_old(p)).
  void rebase_cs(const machines::Frame& before, AxisValues& position) const;
  /// Before modal.kinematics_on changes to `on`: X/Y/Z (and A/B/C for a 6-axis kinematic)
  /// through kinematic `kin_id`'s forward (on) or inverse transform; the kinematic's error
  /// (292005: not configured) otherwise.
  std::optional<machines::KinError> rebase_trafo(bool on, std::optional<int> kin_id,
                                                 AxisValues& position);
  /// The position after #SYNC IN (`in`) or OUT, for the belt travel 0.
  AxisValues sync_rebased(bool in, const AxisValues& position) const;

 private:
  Eigen::Vector3d xyz_of(const AxisValues& values) const;
  void set_xyz(AxisValues& values, const Eigen::Vector3d& p) const;

  const machines::Machine& machine_;
  const machines::CsStack& cs_;
  const ModalSnapshot& modal_;
  const Xyz& xyz_;
  Xyz abc_{};  // machine indices of A, B, C (a 6-axis kinematic's orientation slots)
  std::unique_ptr<machines::Kinematics> kinematic_;  // built at #TRAFO ON for its id
};

}  // namespace ncsim::interp

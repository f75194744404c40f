#pragma once
// machines/frame: rigid transforms between the coordinate systems of the frame chain.
//
//   PCS (programmed, inside the #CS stack) -> PCS1 (co-moving with the conveyor)
//     -> PCS0 (Cartesian basic system, T0) -> MCS -> kinematics -> ACS
//
// A Frame maps coordinates given in a child system into its parent: p_parent = R * p_child + t.
// Inputs: translations in mm, rotation angles in degrees with a rotation sequence
// (P-CHAN-00394, 12 options). Outputs: Frame values with compose / inverse / apply.
// Invariants: `rotation` is orthonormal with determinant +1 (built only from angles or by
// composing frames); all functions are pure and never throw.
//
// Decision (docs/machines.md "Frames"): the three angles of a sequence belong to its three
// letters in order, as intrinsic rotations: sequence "ZYX" with (p1, p2, p3) gives
// R = Rz(p1) * Ry(p2) * Rx(p3). T0 (P-CHAN-00371..00373) uses A about X, B about Y, C about Z
// applied as R = Rz(C) * Ry(B) * Rx(A).

#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <string_view>

namespace ncsim::machines {

/// The 12 rotation sequences: 6 Tait-Bryan and 6 proper Euler orders.
enum class RotationSequence { XYZ, XZY, YXZ, YZX, ZXY, ZYX, XYX, XZX, YXY, YZY, ZXZ, ZYZ };

/// "ZYX" -> RotationSequence::ZYX; nullopt for anything else (case-sensitive).
std::optional<RotationSequence> parse_rotation_sequence(std::string_view text);
std::string_view to_string(RotationSequence sequence);

struct Frame {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< child axes in parent coords
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();   ///< child origin in parent [mm]

  static Frame identity() { return Frame{}; }
  /// Pure translation [mm].
  static Frame shift(const Eigen::Vector3d& translation_mm);
  /// Translation [mm] plus rotation angles [deg] in the given sequence.
  static Frame from_angles(const Eigen::Vector3d& translation_mm,
                           const std::array<double, 3>& angles_deg, RotationSequence sequence);

  /// p_parent = rotation * p_child + translation.
  Eigen::Vector3d apply(const Eigen::Vector3d& p_child) const {
    return rotation * p_child + translation;
  }
  /// Direction vectors: rotation only.
  Eigen::Vector3d apply_vector(const Eigen::Vector3d& v_child) const { return rotation * v_child; }
  Frame inverse() const;
  /// (outer * inner).apply(p) == outer.apply(inner.apply(p)).
  friend Frame operator*(const Frame& outer, const Frame& inner);
};

/// Rotation matrix of one sequence and its angles [deg].
Eigen::Matrix3d rotation_from_angles(const std::array<double, 3>& angles_deg,
                                     RotationSequence sequence);

/// The T0 frame PCS0 -> MCS from P-CHAN-00368..00373 values already converted to mm / deg.
Frame t0_frame(const Eigen::Vector3d& shift_mm, const Eigen::Vector3d& rot_abc_deg);

}  // namespace ncsim::machines

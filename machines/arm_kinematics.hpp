#pragma once
// machines/arm_kinematics: 6-axis articulated robot for #KIN ID[45].
//
// TF5240's coupling-kinematics page lists kinematic 45 as "6-axis articulated robot"; the public
// manuals give neither its geometry nor the meaning of its parameters. Both are ncsim's
// decision (docs/machines.md "Kinematic 45"), trafo[0].param[k] in 0.1 um / 0.0001 deg:
//   param[0..2]   x, y, z of the base (foot of joint 1's axis) in MCS            [0.1 um]
//   param[3]      d1: height of the shoulder axis (joint 2) above the base       [0.1 um]
//   param[4]      a1: shoulder offset from joint 1's axis, along the arm         [0.1 um]
//   param[5]      a2: upper arm, joint 2 to joint 3                              [0.1 um]
//   param[6]      a3: elbow offset, perpendicular to the forearm                 [0.1 um]
//   param[7]      d4: forearm, elbow to the wrist centre along joint 4's axis    [0.1 um]
//   param[8]      d6: wrist centre to the flange along joint 6's axis            [0.1 um]
//   param[9]      tool: flange to TCP along joint 6's axis                       [0.1 um]
//   param[10]     solution code 0..7 (integer as written): bit 0 shoulder back, bit 1 elbow
//                 down, bit 2 wrist flipped (q5 < 0)
//   param[11..22] lower / upper limit of joint 1, 2, ..., 6 (pairs)              [0.0001 deg]
//   param[23]     wrist singular band: |q5| and 180 - |q5| at least this (0: 1 deg) [0.0001 deg]
// Geometry (all joints at 0: upper arm vertical, forearm horizontal along +X, flange axis along
// +X): joint 1 turns about the base's +Z; joints 2 and 3 about the arm's horizontal normal,
// positive tilting the arm forward/down; joints 4, 5, 6 form a spherical wrist, the flange
// orientation R_F(q1, q2 + q3) * Rz(q4) * Ry(q5) * Rz(q6), R_F turning +Z onto the forearm.
// MCS slots: X, Y, Z the TCP [mm]; A, B, C the tool orientation [deg] as
// R = Rz(C) Ry(B) Rx(A) Ry(180 deg): A = B = C = 0 is the tool pointing down (-Z), the
// flange's x along -X.
// Inverse: the closed form of a spherical wrist on the configured solution (param[10]); one
// solution everywhere, so a path never jumps between solutions; joints 1, 4, 6 come in
// (-180, 180], their limits must lie within it (validate()).
// Errors (values): NC3201 outside the reach, NC3202 joint outside its limits, NC3203 unusable
// parameters, NC3204 singular position (wrist: q5 within the band of 0 or 180 deg; shoulder:
// the wrist centre within kShoulderSingular of joint 1's axis).

#include <array>

#include "machines/kinematics.hpp"

namespace ncsim::machines {

/// Wrist centre this close to joint 1's axis is the shoulder singularity [mm].
inline constexpr double kShoulderSingular = 1.0;
/// Wrist singular band when param[23] is 0 [deg].
inline constexpr double kWristBandDefault = 1.0;

/// The solution (configuration) the inverse takes, param[10].
struct ArmSolution {
  bool shoulder_back = false;  ///< bit 0: the wrist centre behind joint 1's axis
  bool elbow_down = false;     ///< bit 1: the elbow below the shoulder-wrist line
  bool wrist_flip = false;     ///< bit 2: q5 < 0
  int code() const { return (shoulder_back ? 1 : 0) | (elbow_down ? 2 : 0) | (wrist_flip ? 4 : 0); }
  bool operator==(const ArmSolution&) const = default;
};

struct ArmGeometry {
  Eigen::Vector3d base_mm = Eigen::Vector3d::Zero();  ///< foot of joint 1's axis in MCS [mm]
  double d1 = 0.0;                                    ///< shoulder height [mm]
  double a1 = 0.0;                                    ///< shoulder offset [mm]
  double a2 = 0.0;                                    ///< upper arm [mm]
  double a3 = 0.0;                                    ///< elbow offset [mm]
  double d4 = 0.0;                                    ///< forearm [mm]
  double d6 = 0.0;                                    ///< wrist centre to flange [mm]
  double tool = 0.0;                                  ///< flange to TCP [mm]
  double solution_raw = 0.0;                          ///< param[10] as read (code x 1e-4)
  ArmSolution solution;                               ///< decoded param[10]
  std::array<double, 6> joint_min_deg{};              ///< [deg]
  std::array<double, 6> joint_max_deg{};              ///< [deg]
  double wrist_band_deg = kWristBandDefault;          ///< [deg]
};

class ArmKinematics final : public Kinematics {
 public:
  static constexpr int kId = 45;
  explicit ArmKinematics(const ArmGeometry& geometry) : g_(geometry) {}
  int id() const override { return kId; }
  std::size_t axis_count() const override { return 6; }
  /// Not a 3-axis kinematic: an NC3203 value naming the slots to use.
  KinResult forward(const Eigen::Vector3d& acs) const override;
  KinResult inverse(const Eigen::Vector3d& mcs) const override;
  /// Joints q1..q6 [deg] -> TCP [mm] and A, B, C [deg]; NC3202 outside a joint's limits.
  KinAxesResult forward_axes(const KinAxes& acs) const override;
  /// TCP and A, B, C -> joints on the configured solution; NC3201 / NC3202 / NC3204.
  KinAxesResult inverse_axes(const KinAxes& mcs) const override;
  /// The same on solution `s` (the configured one aside).
  KinAxesResult inverse_on(const KinAxes& mcs, const ArmSolution& s) const;
  /// The solution joints `q` [deg] stand in (the inverse of inverse_on's choice).
  ArmSolution solution_of(const KinAxes& q) const;
  const ArmGeometry& geometry() const { return g_; }

 private:
  ArmGeometry g_;
};

/// Checks lengths, the solution code and the limits; nullopt when the geometry can be used.
std::optional<KinError> validate(const ArmGeometry& geometry);

/// Geometry from trafo parameters in internal units (mm, deg), mapping above.
ArmGeometry arm_geometry_from_params(std::span<const double> params);

}  // namespace ncsim::machines

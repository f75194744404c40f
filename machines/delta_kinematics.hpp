#pragma once
// machines/delta_kinematics: 3-arm rotary delta robot (Clavel type) for #KIN ID[37].
//
// The public manuals do not define kinematic 37 (isg-language.md §8); the geometry and the
// meaning of trafo[0].param[k] are ncsim's decision (docs/machines.md "Kinematic 37"):
//   param[0..2]  x, y, z of the base centre in MCS                 [0.1 um]
//   param[3]     effector radius r_e (centre to lower ball joints)  [0.1 um]
//   param[4]     base radius r_b (centre to drive axes)             [0.1 um]
//   param[5]     lower arm (parallelogram) length l_b               [0.1 um]
//   param[6]     upper arm length l_a                                [0.1 um]
//   param[7..9]  drive zero offsets (axis value when arm horizontal) [0.0001 deg]
//   param[10]    lower joint limit, param[11] upper joint limit      [0.0001 deg]
//   param[12]    TCP distance below the effector plane               [0.1 um]
// The TF5264 pick & place listing (seed 004 §4.9.1) gives r_e 48 mm, r_b 200 mm, l_b 1050 mm,
// l_a 465.544 mm, limits +-180 deg: it fits this reading.
// Geometry: arm i (i = 0, 1, 2) points along azimuth 120 deg * i from +X; the drive angle
// theta is measured from the horizontal, positive downwards; the effector stays parallel to
// the base. Inverse: the branch with the elbow outside the shoulder-wrist line (theta =
// phi - acos(K / r)); forward: the lower of the two sphere intersections.
// Errors (values): NC3201 point outside the workspace, NC3202 joint outside its limits.

#include <array>

#include "machines/kinematics.hpp"

namespace ncsim::machines {

struct DeltaGeometry {
  Eigen::Vector3d base_mm = Eigen::Vector3d::Zero();  ///< base centre in MCS [mm]
  double r_effector = 0.0;                            ///< [mm]
  double r_base = 0.0;                                ///< [mm]
  double l_lower = 0.0;                               ///< [mm]
  double l_upper = 0.0;                               ///< [mm]
  std::array<double, 3> zero_offset_deg{0, 0, 0};     ///< [deg]
  double joint_min_deg = -180.0;                      ///< [deg]
  double joint_max_deg = 180.0;                       ///< [deg]
  double tcp_offset = 0.0;                            ///< [mm] below the effector plane
};

class DeltaKinematics final : public Kinematics {
 public:
  static constexpr int kId = 37;
  explicit DeltaKinematics(const DeltaGeometry& geometry) : g_(geometry) {}
  int id() const override { return kId; }
  KinResult forward(const Eigen::Vector3d& acs) const override;
  KinResult inverse(const Eigen::Vector3d& mcs) const override;
  const DeltaGeometry& geometry() const { return g_; }

 private:
  DeltaGeometry g_;
};

/// Checks lengths and limits; nullopt when the geometry can be used.
std::optional<KinError> validate(const DeltaGeometry& geometry);

/// Geometry from trafo parameters in internal units (mm, deg), mapping above.
DeltaGeometry delta_geometry_from_params(std::span<const double> params);

}  // namespace ncsim::machines
